#include "pdo_test_support.hpp"

#include <gtest/gtest.h>
#include <string>
#include <vector>

// PDO transmission and reception over raw frames on a 1 Mbit/s virtual bus (CiA 301 7.2.2,
// transmission types of 7.5.2.37), every frame checked byte for byte and by the time it
// started on the wire.

namespace eposp::canopen {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;
using testing::at_ms;
using testing::at_us;
using testing::configure_pdo;
using testing::end_of_frame;
using testing::next_start_after;
using testing::PdoNode;
using testing::PdoSetup;
using testing::Sent;

constexpr std::uint32_t kStatusword = 0x6041'0010;
constexpr std::uint32_t kControlword = 0x6040'0010;
constexpr std::uint32_t kTargetPosition = 0x607A'0020;

class PdoTest : public ::testing::Test {
protected:
    void configure_tpdo(const PdoSetup& setup) {
        ASSERT_EQ(configure_pdo(node.od, PdoDirection::Transmit, 1, setup), AbortCode::None);
    }
    void configure_rpdo(const PdoSetup& setup) {
        ASSERT_EQ(configure_pdo(node.od, PdoDirection::Receive, 1, setup), AbortCode::None);
    }
    void set_statusword(std::uint16_t value) { node.od.set_as(0x6041, 0, value); }
    void at(core::TimePoint when, std::function<void()> fn) { node.loop.at(when, std::move(fn)); }

    /// SYNCs every millisecond from now; with counters first, first + 1, ..., overflow, 1, ...
    /// when overflow is not 0.
    void schedule_syncs(int count, int overflow = 0, int first_counter = 1) {
        const core::TimePoint first = node.loop.now();
        for (int k = 0; k < count; ++k) {
            const auto counter = static_cast<std::uint8_t>(
                overflow == 0 ? 0 : (first_counter - 1 + k) % overflow + 1);
            at(first + milliseconds(k), [this, counter] { node.sync(counter); });
        }
    }
    /// `frame`, sent right after each of the tester's frames `indices`.
    std::vector<Sent> right_after(std::initializer_list<std::size_t> indices,
                                  const std::string& frame) const {
        const auto requests = node.tester_frames();
        std::vector<Sent> out;
        for (const std::size_t i : indices) {
            out.push_back({next_start_after(requests.at(i)), frame});
        }
        return out;
    }

    PdoNode node;
};

class TpdoSync : public PdoTest {};
class TpdoRtr : public PdoTest {};
class TpdoEvent : public PdoTest {};
class TpdoState : public PdoTest {};
class RpdoReception : public PdoTest {};
class PdoServiceDispatch : public PdoTest {};

// ---- synchronous TPDOs ----

TEST_F(TpdoSync, TypeOneIsSentAtEverySync) {
    set_statusword(0x0237);
    configure_tpdo({0x185, 1, {kStatusword}});
    node.operational();
    schedule_syncs(4);
    node.run_for(milliseconds(5));
    EXPECT_EQ(node.device_frames(), right_after({0, 1, 2, 3}, "185#3702"));
}

TEST_F(TpdoSync, TypeThreeIsSentAtEveryThirdSync) {
    configure_tpdo({0x185, 3, {kStatusword}});
    node.operational();
    schedule_syncs(9);
    node.run_for(milliseconds(10));
    EXPECT_EQ(node.device_frames(), right_after({2, 5, 8}, "185#0000"));
}

TEST_F(TpdoSync, FirstSentAtTheSyncWhoseCounterIsTheStartValue) {
    PdoSetup setup{0x185, 2, {kStatusword}};
    setup.sync_start = 3;
    configure_tpdo(setup);
    node.operational();
    schedule_syncs(10, 10); // counters 1..10
    node.run_for(milliseconds(11));
    EXPECT_EQ(node.device_frames(), right_after({2, 4, 6, 8}, "185#0000"));
}

TEST_F(TpdoSync, StartValueWaitsAcrossTheCounterOverflow) {
    PdoSetup setup{0x185, 3, {kStatusword}};
    setup.sync_start = 2;
    configure_tpdo(setup);
    node.operational();
    schedule_syncs(10, 4, 3); // counters 3 4 1 2 3 4 1 2 3 4
    node.run_for(milliseconds(11));
    EXPECT_EQ(node.device_frames(), right_after({3, 6, 9}, "185#0000"));
}

TEST_F(TpdoSync, StartValueIsUnusedWhenTheSyncHasNoCounter) {
    PdoSetup setup{0x185, 2, {kStatusword}};
    setup.sync_start = 3;
    configure_tpdo(setup);
    node.operational();
    schedule_syncs(6);
    node.run_for(milliseconds(7));
    EXPECT_EQ(node.device_frames(), right_after({1, 3, 5}, "185#0000"));
}

TEST_F(TpdoSync, CyclicTypeIgnoresChangesBetweenSyncs) {
    configure_tpdo({0x185, 1, {kStatusword}});
    node.operational();
    schedule_syncs(2);
    at(at_us(500), [this] { set_statusword(0x0011); });
    node.run_for(milliseconds(3));
    const auto first = right_after({0}, "185#0000");
    const auto second = right_after({1}, "185#1100");
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{first[0], second[0]}));
}

TEST_F(TpdoSync, AcyclicTypeIsSentAtTheSyncAfterAnEvent) {
    configure_tpdo({0x185, 0, {kStatusword}});
    node.operational(); // becoming active is an event: sent at the first SYNC
    schedule_syncs(5);
    at(at_us(1500), [this] { set_statusword(0x0011); });
    at(at_us(3500), [this] { node.pdo->tpdo(1).trigger(); });
    node.run_for(milliseconds(6));
    const auto initial = right_after({0}, "185#0000");
    const auto changed = right_after({2}, "185#1100");
    const auto triggered = right_after({4}, "185#1100");
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{initial[0], changed[0], triggered[0]}));
}

// ---- RTR ----

TEST_F(TpdoRtr, Type252AnswersWithTheDataSampledAtTheLastSync) {
    configure_tpdo({0x185, kRtrSynchronous, {kStatusword}});
    node.operational();
    node.send("185#R2"); // nothing sampled yet: no answer
    at(at_ms(1), [this] {
        set_statusword(0x0001);
        node.sync();
    });
    at(at_us(1500), [this] { set_statusword(0x0002); });
    at(at_ms(2), [this] { node.send("185#R2"); });
    node.run_for(milliseconds(3));
    EXPECT_EQ(node.device_frames(), right_after({2}, "185#0100"));
}

TEST_F(TpdoRtr, Type253IsSentOnlyOnRequestWithTheCurrentData) {
    configure_tpdo({0x185, kRtrEventDriven, {kStatusword}});
    node.operational();
    schedule_syncs(2);
    at(at_us(1500), [this] { set_statusword(0x0042); });
    at(at_ms(3), [this] { node.send("185#R2"); });
    node.run_for(milliseconds(4));
    EXPECT_EQ(node.device_frames(), right_after({2}, "185#4200"));
}

TEST_F(TpdoRtr, IgnoredWhereTheCobIdForbidsRtr) {
    configure_tpdo({PdoCobId::kNoRtr | 0x185, kRtrEventDriven, {kStatusword}});
    node.operational();
    node.send("185#R2");
    node.run_for(milliseconds(1));
    EXPECT_TRUE(node.device_frames().empty());
}

TEST_F(TpdoRtr, EventDrivenTypeAnswers) {
    configure_tpdo({0x185, kEventDrivenProfile, {kStatusword}});
    node.operational();
    at(at_ms(1), [this] { node.send("185#R2"); });
    node.run_for(milliseconds(2));
    const auto answer = right_after({0}, "185#0000");
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{{at_ms(0), "185#0000"}, answer[0]}));
}

TEST_F(TpdoRtr, CyclicTypeIgnoresIt) {
    configure_tpdo({0x185, 1, {kStatusword}});
    node.operational();
    node.send("185#R2");
    node.run_for(milliseconds(1));
    EXPECT_TRUE(node.device_frames().empty());
}

// ---- event-driven TPDOs ----

TEST_F(TpdoEvent, SentOnEnteringOperationalAndOnEveryChange) {
    configure_tpdo({0x185, kEventDrivenProfile, {kStatusword}});
    node.operational();
    at(at_ms(1), [this] { set_statusword(0x0011); });
    at(at_ms(2), [this] { set_statusword(0x0011); }); // same data: no event
    at(at_ms(3), [this] { set_statusword(0x0022); });
    node.run_for(milliseconds(4));
    EXPECT_EQ(node.device_frames(),
              (std::vector<Sent>{
                  {at_ms(0), "185#0000"}, {at_ms(1), "185#1100"}, {at_ms(3), "185#2200"}}));
}

TEST_F(TpdoEvent, InhibitTimeHoldsTheNextTransmissionBackUntilItEnds) {
    PdoSetup setup{0x185, kEventDrivenManufacturer, {kStatusword}};
    setup.inhibit_time = 10; // 1 ms
    configure_tpdo(setup);
    node.operational();
    at(at_us(200), [this] { set_statusword(0x0011); });
    at(at_us(500), [this] { set_statusword(0x0022); });
    at(at_ms(3), [this] { set_statusword(0x0033); });
    at(at_us(3100), [this] { node.pdo->tpdo(1).trigger(); });
    node.run_for(milliseconds(5));
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{{at_ms(0), "185#0000"},
                                                       {at_ms(1), "185#2200"},
                                                       {at_ms(3), "185#3300"},
                                                       {at_ms(4), "185#3300"}}));
}

TEST_F(TpdoEvent, ChangeUndoneDuringTheInhibitTimeSendsNothing) {
    PdoSetup setup{0x185, kEventDrivenProfile, {kStatusword}};
    setup.inhibit_time = 10;
    configure_tpdo(setup);
    node.operational();
    at(at_us(200), [this] { set_statusword(0x0011); });
    at(at_us(400), [this] { set_statusword(0x0000); });
    node.run_for(milliseconds(3));
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{{at_ms(0), "185#0000"}}));
}

TEST_F(TpdoEvent, EventTimerSendsWhenNothingChanges) {
    PdoSetup setup{0x185, kEventDrivenProfile, {kStatusword}};
    setup.event_timer = 10;
    configure_tpdo(setup);
    node.operational();
    node.run_for(milliseconds(35));
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{{at_ms(0), "185#0000"},
                                                       {at_ms(10), "185#0000"},
                                                       {at_ms(20), "185#0000"},
                                                       {at_ms(30), "185#0000"}}));
}

TEST_F(TpdoEvent, EveryTransmissionRestartsTheEventTimer) {
    PdoSetup setup{0x185, kEventDrivenProfile, {kStatusword}};
    setup.event_timer = 10;
    configure_tpdo(setup);
    node.operational();
    at(at_ms(4), [this] { set_statusword(0x0011); });
    node.run_for(milliseconds(25));
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{{at_ms(0), "185#0000"},
                                                       {at_ms(4), "185#1100"},
                                                       {at_ms(14), "185#1100"},
                                                       {at_ms(24), "185#1100"}}));
}

TEST_F(TpdoEvent, EventTimerWaitsForTheInhibitTime) {
    PdoSetup setup{0x185, kEventDrivenProfile, {kStatusword}};
    setup.event_timer = 1;
    setup.inhibit_time = 20; // 2 ms
    configure_tpdo(setup);
    node.operational();
    node.run_for(milliseconds(5));
    EXPECT_EQ(node.device_frames(),
              (std::vector<Sent>{
                  {at_ms(0), "185#0000"}, {at_ms(2), "185#0000"}, {at_ms(4), "185#0000"}}));
}

TEST_F(TpdoEvent, ApplicationEventSendsUnchangedData) {
    configure_tpdo({0x185, kEventDrivenProfile, {kStatusword}});
    node.operational();
    at(at_ms(2), [this] { node.pdo->tpdo(1).trigger(); });
    node.run_for(milliseconds(3));
    EXPECT_EQ(node.device_frames(),
              (std::vector<Sent>{{at_ms(0), "185#0000"}, {at_ms(2), "185#0000"}}));
}

TEST_F(TpdoEvent, TransmissionTypeChangedWhileOperationalTakesEffect) {
    configure_tpdo({0x185, 1, {kStatusword}});
    node.operational();
    ASSERT_EQ(testing::write_as(node.od, 0x1800, 2, kEventDrivenProfile), AbortCode::None);
    at(at_ms(1), [this] { set_statusword(0x0011); });
    node.run_for(milliseconds(2));
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{{at_ms(1), "185#1100"}}));
}

// ---- NMT state, validity, collisions ----

TEST_F(TpdoState, SendsNothingOutsideOperational) {
    configure_tpdo({0x185, kEventDrivenProfile, {kStatusword}});
    ASSERT_EQ(configure_pdo(node.od, PdoDirection::Transmit, 2, {0x285, 1, {kStatusword}}),
              AbortCode::None);
    ASSERT_EQ(
        configure_pdo(node.od, PdoDirection::Transmit, 3, {0x385, kRtrEventDriven, {kStatusword}}),
        AbortCode::None);
    for (const NmtState state : {NmtState::PreOperational, NmtState::Stopped}) {
        node.pdo->set_nmt_state(state);
        node.sync();
        set_statusword(static_cast<std::uint16_t>(state));
        node.pdo->tpdo(1).trigger();
        node.send("385#R2");
        node.run_for(milliseconds(1));
    }
    EXPECT_TRUE(node.device_frames().empty());
}

TEST_F(TpdoState, LeavingOperationalStopsTheEventTimer) {
    PdoSetup setup{0x185, kEventDrivenProfile, {kStatusword}};
    setup.event_timer = 10;
    configure_tpdo(setup);
    node.operational();
    at(at_ms(15), [this] { node.pdo->set_nmt_state(NmtState::PreOperational); });
    at(at_ms(35), [this] { node.operational(); });
    node.run_for(milliseconds(40));
    EXPECT_EQ(node.device_frames(),
              (std::vector<Sent>{
                  {at_ms(0), "185#0000"}, {at_ms(10), "185#0000"}, {at_ms(35), "185#0000"}}));
}

TEST_F(TpdoState, InvalidOrUnmappedSendsNothing) {
    configure_tpdo({PdoCobId::kInvalid | 0x185, kEventDrivenProfile, {kStatusword}});
    ASSERT_EQ(configure_pdo(node.od, PdoDirection::Transmit, 2, {0x285, kEventDrivenProfile, {}}),
              AbortCode::None);
    node.operational();
    set_statusword(0x0011);
    node.pdo->tpdo(1).trigger();
    node.pdo->tpdo(2).trigger();
    node.run_for(milliseconds(1));
    EXPECT_TRUE(node.device_frames().empty());
    EXPECT_FALSE(node.pdo->tpdo(1).active());
    EXPECT_FALSE(node.pdo->tpdo(2).active());
}

TEST_F(TpdoState, ValidatingItWhileOperationalStartsIt) {
    configure_tpdo({PdoCobId::kInvalid | 0x185, kEventDrivenProfile, {kStatusword}});
    node.operational();
    at(at_ms(1),
       [this] { ASSERT_EQ(testing::write_as(node.od, 0x1800, 1, 0x185U), AbortCode::None); });
    node.run_for(milliseconds(2));
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{{at_ms(1), "185#0000"}}));
}

// EPOS2 FW spec 4.2.20: another node sends with our TPDO's COB-ID.
TEST_F(TpdoState, DataFrameWithItsCobIdRaisesCollisionEmergency) {
    configure_tpdo({0x185, 1, {kStatusword}});
    node.operational();
    node.send("185#0000");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.emcy, (std::vector<std::uint16_t>{kEmcyTransmitCobIdCollision}));
}

TEST_F(TpdoState, With29BitCobIdSendsExtendedFrames) {
    configure_tpdo({PdoCobId::kExtended | 0x0123'4567, kEventDrivenProfile, {kStatusword}});
    node.operational();
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{{at_ms(0), "01234567#0000"}}));
}

TEST(PdoEpos2, DefaultTpdo1SendsTheStatuswordOnChangeAndTpdo4OnlyOnceValid) {
    PdoNode node(epos2_pdo_defaults(testing::kNode));
    node.operational();
    node.loop.at(at_ms(1), [&node] { node.od.set_as(0x6041, 0, std::uint16_t{0x0640}); });
    node.send("485#R6"); // TPDO 4 is not valid by default
    node.run_for(milliseconds(2));
    EXPECT_EQ(node.device_frames(),
              (std::vector<Sent>{{at_ms(0), "185#0000"}, {at_ms(1), "185#4006"}}));
}

// ---- RPDOs ----

TEST_F(RpdoReception, EventDrivenTypeStoresItsDataOnReception) {
    configure_rpdo({0x205, kEventDrivenProfile, {kControlword, kTargetPosition}});
    node.operational();
    std::vector<core::TimePoint> stored_at;
    node.od.on_change(0x607A,
                      [&](std::uint16_t, std::uint8_t) { stored_at.push_back(node.loop.now()); });
    node.send("205#0F00E8030000");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x000F);
    EXPECT_EQ(node.od.get_as<std::int32_t>(0x607A, 0), 1000);
    EXPECT_EQ(stored_at, (std::vector<core::TimePoint>{end_of_frame(node.tester_frames()[0])}));
    EXPECT_TRUE(node.emcy.empty());
}

TEST_F(RpdoReception, SynchronousTypeStoresTheLastDataAtTheNextSync) {
    configure_rpdo({0x205, 1, {kControlword}});
    node.operational();
    std::vector<core::TimePoint> stored_at;
    node.od.on_change(0x6040,
                      [&](std::uint16_t, std::uint8_t) { stored_at.push_back(node.loop.now()); });
    node.send("205#0F00");
    node.send("205#1F00");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0);
    node.sync();
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x001F);
    EXPECT_EQ(stored_at, (std::vector<core::TimePoint>{end_of_frame(node.tester_frames()[2])}));
    node.sync(); // nothing new: nothing stored
    node.run_for(milliseconds(1));
    EXPECT_EQ(stored_at.size(), 1U);
}

TEST_F(RpdoReception, ShorterThanItsMappingIsNotProcessedAndRaisesLengthError) {
    configure_rpdo({0x205, kEventDrivenProfile, {kControlword, kTargetPosition}});
    node.operational();
    node.send("205#0F00E80300");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0);
    EXPECT_EQ(node.od.get_as<std::int32_t>(0x607A, 0), 0);
    EXPECT_EQ(node.emcy, (std::vector<std::uint16_t>{kEmcyPdoLengthError}));
}

TEST_F(RpdoReception, LongerThanItsMappingIsProcessedAndRaisesLengthExceeded) {
    configure_rpdo({0x205, kEventDrivenProfile, {kControlword}});
    node.operational();
    node.send("205#0F00AABB");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x000F);
    EXPECT_EQ(node.emcy, (std::vector<std::uint16_t>{kEmcyPdoLengthExceeded}));
}

TEST_F(RpdoReception, IgnoresFramesOutsideOperational) {
    configure_rpdo({0x205, kEventDrivenProfile, {kControlword}});
    for (const NmtState state : {NmtState::PreOperational, NmtState::Stopped}) {
        node.pdo->set_nmt_state(state);
        node.send("205#0F");
        node.send("205#0F00");
        node.run_for(milliseconds(1));
    }
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0);
    EXPECT_TRUE(node.emcy.empty());
}

TEST_F(RpdoReception, LeavingOperationalDropsSynchronousDataNotYetStored) {
    configure_rpdo({0x205, 1, {kControlword}});
    node.operational();
    node.send("205#0F00");
    node.run_for(milliseconds(1));
    node.pdo->set_nmt_state(NmtState::PreOperational);
    node.operational();
    node.sync();
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0);
}

TEST_F(RpdoReception, IgnoresRemoteFramesOtherIdsAndItsIdWhileInvalid) {
    configure_rpdo({0x205, kEventDrivenProfile, {kControlword}});
    node.operational();
    node.send("205#R2");
    node.send("206#0F00");
    node.send("00000205#0F00");
    node.run_for(milliseconds(1));
    ASSERT_EQ(testing::write_as(node.od, 0x1400, 1, 0x8000'0205U), AbortCode::None);
    node.send("205#0F00");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0);
    EXPECT_TRUE(node.emcy.empty());
}

// The service skips frames that are no PDO's: a COB-ID changed later (invalid, new identifier,
// valid again) must be heard on the new identifier and no longer on the old one.
TEST_F(RpdoReception, CobIdChangedLaterIsReceivedOnTheNewIdentifier) {
    configure_rpdo({0x205, kEventDrivenProfile, {kControlword}});
    node.operational();
    node.send("205#0100");
    node.run_for(milliseconds(1));
    ASSERT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x0001);
    ASSERT_EQ(testing::write_as(node.od, 0x1400, 1, 0x8000'0321U), AbortCode::None);
    ASSERT_EQ(testing::write_as(node.od, 0x1400, 1, 0x0000'0321U), AbortCode::None);
    node.send("205#0200");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x0001);
    node.send("321#0F00");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x000F);
}

TEST_F(RpdoReception, With29BitCobIdTakesExtendedFrames) {
    configure_rpdo({PdoCobId::kExtended | 0x0123'4567, kEventDrivenProfile, {kControlword}});
    node.operational();
    node.send("567#0100"); // the same low 11 bits in a base frame
    node.send("01234567#0F00");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x000F);
}

TEST(PdoEpos2, DefaultRpdo2StoresControlwordAndModeOfOperation) {
    PdoNode node(epos2_pdo_defaults(testing::kNode));
    node.operational();
    node.send("305#0F00FF");
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x000F);
    EXPECT_EQ(node.od.get_as<std::int8_t>(0x6060, 0), -1);
}

// ---- the service ----

TEST_F(PdoServiceDispatch, AtSyncTpdosSampleBeforeRpdosStore) {
    configure_rpdo({0x205, 1, {kControlword}});
    configure_tpdo({0x185, 1, {kControlword}});
    node.operational();
    node.send("205#3412");
    at(at_ms(1), [this] { node.sync(); });
    at(at_ms(2), [this] { node.sync(); });
    node.run_for(milliseconds(3));
    const auto first = right_after({1}, "185#0000");
    const auto second = right_after({2}, "185#3412");
    EXPECT_EQ(node.device_frames(), (std::vector<Sent>{first[0], second[0]}));
}

// SYNC reaches only the synchronous PDOs, listed as their parameters change: a TPDO made
// synchronous while operational answers the next SYNC, whether a remote write or a local one
// followed by reload() changed it.
TEST_F(PdoServiceDispatch, TpdoMadeSynchronousAtRunTimeAnswersTheNextSync) {
    configure_tpdo({0x185, kEventDrivenProfile, {kStatusword}});
    ASSERT_EQ(configure_pdo(node.od, PdoDirection::Transmit, 2,
                            {0x285, kEventDrivenProfile, {kStatusword}}),
              AbortCode::None);
    node.operational();
    node.run_for(milliseconds(1)); // the transmissions of becoming active
    const std::size_t before = node.device_frames().size();
    ASSERT_EQ(testing::write_as(node.od, 0x1800, 2, std::uint8_t{1}), AbortCode::None);
    node.od.set_as(0x1801, 2, std::uint8_t{2});
    node.pdo->reload();
    schedule_syncs(2);
    node.run_for(milliseconds(3));
    const auto frames = node.device_frames();
    ASSERT_EQ(frames.size(), before + 3);
    EXPECT_EQ(frames[before], right_after({0}, "185#0000")[0]);
    EXPECT_EQ(frames[before + 1], right_after({1}, "185#0000")[0]);
    EXPECT_EQ(frames[before + 2], (Sent{next_start_after(frames[before + 1]), "285#0000"}))
        << "TPDO 2, every second SYNC, follows TPDO 1 at the second";
}

// An RPDO made synchronous after the window of the last SYNC closed discards what it receives
// until the next SYNC (CiA 301 7.5.2.8), although it was not synchronous when the window closed.
TEST_F(PdoServiceDispatch, RpdoMadeSynchronousWhileTheWindowIsClosedWaitsForTheNextSync) {
    configure_rpdo({0x205, kEventDrivenProfile, {kControlword}});
    node.operational();
    node.sync();
    node.run_for(milliseconds(1));
    node.pdo->on_window_closed();
    configure_rpdo({0x205, 1, {kControlword}});
    node.send("205#0F00"); // after the window: discarded
    node.run_for(milliseconds(1));
    node.sync();
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0);
    node.send("205#1F00"); // inside the window of this SYNC: stored at the next
    node.run_for(milliseconds(1));
    node.sync();
    node.run_for(milliseconds(1));
    EXPECT_EQ(node.od.get_as<std::uint16_t>(0x6040, 0), 0x001F);
}

TEST_F(PdoServiceDispatch, HasAPdoForEveryCommunicationObject) {
    EXPECT_EQ(node.pdo->rpdo_count(), 4U);
    EXPECT_EQ(node.pdo->tpdo_count(), 4U);
    EXPECT_EQ(node.pdo->tpdo(4).number(), 4U);
    EXPECT_THROW(node.pdo->rpdo(5), std::out_of_range);
    EXPECT_THROW(node.pdo->tpdo(0), std::out_of_range);
}

TEST_F(PdoServiceDispatch, ReloadFollowsADictionaryResetToDefaults) {
    configure_tpdo({0x185, kEventDrivenProfile, {kStatusword}});
    node.operational();
    node.run_for(milliseconds(1));
    ASSERT_TRUE(node.pdo->tpdo(1).active());
    node.od.reset_to_defaults();
    node.pdo->reload();
    EXPECT_FALSE(node.pdo->tpdo(1).active());
}

} // namespace
} // namespace eposp::canopen
