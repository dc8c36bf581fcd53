#include "service_bench.hpp"
#include "eposp/canopen/guarding_master.hpp"
#include "eposp/canopen/heartbeat_producer.hpp"
#include "eposp/canopen/nmt_slave.hpp"
#include "eposp/canopen/node_guarding.hpp"

#include <deque>
#include <gtest/gtest.h>
#include <optional>
#include <utility>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::after_intermission;
using testing::at_ms;
using testing::Sent;
using testing::ServiceBench;
using testing::write_as;

constexpr NodeId kNode = 5;

// ---------------------------------------------------------------------------------------------
// Slave: node guarding and life guarding

/// A booted slave with NMT and node guarding (and the 0x1017 object); the tester is the
/// guarding master.
class NodeGuardingTest : public ::testing::Test {
protected:
    NodeGuardingTest() {
        add_heartbeat_producer_object(od);
        add_node_guarding_objects(od);
        nmt.on_state_change([this](NmtState state) { guarding.set_nmt_state(state); });
        guarding.on_life_guarding_event(
            [this](bool occurred) { events.emplace_back(occurred, bench.loop.now()); });
        bench.device->on_receive([this](const can::Frame& frame) {
            nmt.on_frame(frame);
            guarding.on_frame(frame);
        });
        nmt.boot();
        bench.run_for(1ms);
    }
    /// A guarding request at `t`: returns the bytes of the reply and checks when it started,
    /// or nullopt without a reply.
    std::optional<std::string> request_at(core::TimePoint t) {
        bench.run_until(t);
        const std::size_t before = bench.device_frames().size();
        bench.send("705#R1");
        bench.run_for(1ms);
        const auto frames = bench.device_frames();
        if (frames.size() == before) {
            return std::nullopt;
        }
        const core::TimePoint request_end = bench.wire.events.at(bench.wire.events.size() - 2).end;
        EXPECT_EQ(frames.back().at, after_intermission(request_end));
        return frames.back().frame;
    }
    void configure(std::uint16_t guard_ms, std::uint8_t factor) {
        ASSERT_EQ(write_as(od, kGuardTimeIndex, 0, guard_ms), AbortCode::None);
        ASSERT_EQ(write_as(od, kLifeTimeFactorIndex, 0, factor), AbortCode::None);
    }

    ServiceBench bench;
    ObjectDictionary od;
    std::vector<std::uint16_t> emergencies;
    NmtSlave nmt{*bench.device, kNode, {.application = {}, .communication = [this] {
                                            od.reset_to_defaults();
                                        }}};
    NodeGuarding guarding{bench.loop, *bench.device, od, kNode, [this](std::uint16_t code) {
                              emergencies.push_back(code);
                          }};
    std::vector<std::pair<bool, core::TimePoint>> events;
};

TEST_F(NodeGuardingTest, AnswersWithTheStateAndAToggleThatStartsAtZero) {
    EXPECT_EQ(request_at(at_ms(10)), "705#7F");
    EXPECT_EQ(request_at(at_ms(20)), "705#FF");
    EXPECT_EQ(request_at(at_ms(30)), "705#7F");
    nmt.apply(NmtCommand::Start);
    EXPECT_EQ(request_at(at_ms(40)), "705#85");
    nmt.apply(NmtCommand::Stop);
    EXPECT_EQ(request_at(at_ms(50)), "705#04");
}

TEST_F(NodeGuardingTest, ResetCommunicationStartsTheToggleAtZeroAgain) {
    EXPECT_EQ(request_at(at_ms(10)), "705#7F");
    EXPECT_EQ(request_at(at_ms(20)), "705#FF");
    bench.send("000#8205");
    EXPECT_EQ(request_at(at_ms(30)), "705#7F");
}

TEST_F(NodeGuardingTest, IgnoresFramesThatAreNotItsGuardingRequest) {
    for (const char* frame : {"706#R1", "705#00", "00000705#R1"}) {
        bench.send(frame);
        bench.run_for(1ms);
    }
    EXPECT_EQ(bench.device_frames().size(), 1U); // the boot-up
    EXPECT_EQ(request_at(at_ms(10)), "705#7F");
}

TEST_F(NodeGuardingTest, AnswersNothingWhileTheHeartbeatProducerIsOn) {
    // EPOS2 FW spec 8.2.6: heartbeat and guarding are never used at once.
    ASSERT_EQ(write_as(od, kProducerHeartbeatTimeIndex, 0, std::uint16_t{100}), AbortCode::None);
    EXPECT_EQ(request_at(at_ms(10)), std::nullopt);
    ASSERT_EQ(write_as(od, kProducerHeartbeatTimeIndex, 0, std::uint16_t{0}), AbortCode::None);
    EXPECT_EQ(request_at(at_ms(20)), "705#7F");
}

TEST_F(NodeGuardingTest, LifeGuardingStartsWithTheFirstRequest) {
    configure(100, 3);
    bench.run_until(at_ms(1000));
    EXPECT_TRUE(events.empty());

    request_at(at_ms(1000));
    const core::TimePoint request_end = bench.wire.events.at(bench.wire.events.size() - 2).end;
    bench.run_until(at_ms(2000));

    EXPECT_EQ(events, (std::vector<std::pair<bool, core::TimePoint>>{{true, request_end + 300ms}}));
    EXPECT_EQ(emergencies, (std::vector<std::uint16_t>{0x8130}));
}

TEST_F(NodeGuardingTest, EveryRequestRestartsTheLifeTimeAndTheNextOneResolvesAnEvent) {
    configure(100, 3);
    for (int t = 0; t <= 1000; t += 250) {
        request_at(at_ms(t));
    }
    EXPECT_TRUE(events.empty());
    bench.run_until(at_ms(2000));
    request_at(at_ms(2000));
    ASSERT_EQ(events.size(), 2U);
    EXPECT_TRUE(events[0].first);
    EXPECT_FALSE(events[1].first);
    EXPECT_EQ(emergencies.size(), 1U);
}

TEST_F(NodeGuardingTest, ZeroGuardTimeOrLifeTimeFactorMeansNoLifeGuarding) {
    configure(0, 3);
    request_at(at_ms(0));
    bench.run_until(at_ms(1000));
    configure(100, 0);
    request_at(at_ms(1000));
    bench.run_until(at_ms(2000));
    EXPECT_TRUE(events.empty());
}

TEST_F(NodeGuardingTest, NewGuardTimeCountsFromTheWrite) {
    configure(100, 3);
    request_at(at_ms(0));
    bench.run_until(at_ms(200));
    ASSERT_EQ(write_as(od, kGuardTimeIndex, 0, std::uint16_t{50}), AbortCode::None);
    bench.run_until(at_ms(1000));
    EXPECT_EQ(events, (std::vector<std::pair<bool, core::TimePoint>>{{true, at_ms(350)}}));
}

TEST_F(NodeGuardingTest, ResetOrHeartbeatStopsLifeGuarding) {
    configure(100, 3);
    request_at(at_ms(0));
    nmt.apply(NmtCommand::ResetNode); // restores guard time 0 as well: set it again
    configure(100, 3);
    bench.run_until(at_ms(1000));
    EXPECT_TRUE(events.empty());

    request_at(at_ms(1000));
    ASSERT_EQ(write_as(od, kProducerHeartbeatTimeIndex, 0, std::uint16_t{100}), AbortCode::None);
    bench.run_until(at_ms(2000));
    EXPECT_TRUE(events.empty());
}

// The dictionary's checks are all these objects have (CiA 301 7.5.2, 100Ch/100Dh).
struct GuardingWriteCase {
    const char* what;
    std::uint16_t index;
    Bytes data;
    AbortCode expected;
    friend void PrintTo(const GuardingWriteCase& c, std::ostream* os) { *os << c.what; }
};

class NodeGuardingObjects : public ::testing::TestWithParam<GuardingWriteCase> {};

TEST_P(NodeGuardingObjects, WriteIsCheckedByLength) {
    const GuardingWriteCase& c = GetParam();
    ObjectDictionary od;
    add_node_guarding_objects(od);
    EXPECT_EQ(od.write(c.index, 0, c.data), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    NodeGuardingCiA301, NodeGuardingObjects,
    ::testing::Values(
        GuardingWriteCase{"guard time", 0x100C, {0xE8, 0x03}, AbortCode::None},
        GuardingWriteCase{"guard time too long", 0x100C, {1, 2, 3}, AbortCode::LengthTooHigh},
        GuardingWriteCase{"guard time too short", 0x100C, {1}, AbortCode::LengthTooLow},
        GuardingWriteCase{"life time factor", 0x100D, {255}, AbortCode::None},
        GuardingWriteCase{"life time factor too long", 0x100D, {1, 0}, AbortCode::LengthTooHigh},
        GuardingWriteCase{"no sub-index 1", 0x100D, {}, AbortCode::LengthTooLow}));

TEST(NodeGuardingObjectDefaults, AreZero) {
    ObjectDictionary od;
    add_node_guarding_objects(od);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x100C, 0), 0);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x100D, 0), 0);
    EXPECT_EQ(od.find(0x100C, 0)->access, Access::ReadWrite);
}

// ---------------------------------------------------------------------------------------------
// Master

/// The guarding master on the device port polls node 5; the tester answers each request with
/// the next scripted byte (none when the script has nullopt or is empty).
class NodeGuardingMasterTest : public ::testing::Test {
protected:
    NodeGuardingMasterTest() {
        bench.device->on_receive([this](const can::Frame& frame) { master.on_frame(frame); });
        bench.tester->on_receive([this](const can::Frame& frame) {
            if (!frame.remote || script.empty()) {
                return;
            }
            const std::optional<std::uint8_t> reply = script.front();
            script.pop_front();
            if (reply) {
                bench.tester->send(can::Frame::data_frame(0x705, {*reply}));
            }
        });
        master.on_event(
            [this](GuardingMaster::Event event) { events.emplace_back(event, bench.loop.now()); });
        master.on_state_change([this](NmtState state) { states.push_back(state); });
    }

    ServiceBench bench;
    GuardingMaster master{bench.loop, *bench.device, kNode};
    std::deque<std::optional<std::uint8_t>> script;
    std::vector<std::pair<GuardingMaster::Event, core::TimePoint>> events;
    std::vector<NmtState> states;
};

TEST_F(NodeGuardingMasterTest, PollsAtOnceAndThenEveryGuardTime) {
    master.start(100ms, 3);
    bench.run_until(at_ms(201));
    EXPECT_EQ(
        bench.device_frames(),
        (std::vector<Sent>{{at_ms(0), "705#R1"}, {at_ms(100), "705#R1"}, {at_ms(200), "705#R1"}}));
    master.stop();
    bench.run_until(at_ms(1000));
    EXPECT_EQ(bench.device_frames().size(), 3U);
}

TEST_F(NodeGuardingMasterTest, NodeIsLostAfterLifeTimeFactorUnansweredRequests) {
    master.start(100ms, 3);
    bench.run_until(at_ms(1000));
    // Requests at 0, 100, 200 go unanswered; the one at 300 finds the third missing.
    using enum GuardingMaster::Event;
    EXPECT_EQ(events, (std::vector<std::pair<GuardingMaster::Event, core::TimePoint>>{
                          {NodeLost, at_ms(300)}}));
    EXPECT_EQ(master.remote_state(), std::nullopt);
}

TEST_F(NodeGuardingMasterTest, FollowsTheStateOfAlternatingReplies) {
    script = {0x7F, 0xFF, 0x05, 0x85, 0x04};
    master.start(100ms, 2);
    bench.run_until(at_ms(450));
    EXPECT_TRUE(events.empty());
    EXPECT_EQ(states,
              (std::vector{NmtState::PreOperational, NmtState::Operational, NmtState::Stopped}));
    EXPECT_EQ(master.remote_state(), NmtState::Stopped);
}

TEST_F(NodeGuardingMasterTest, ReplyWithTheWrongToggleDoesNotCount) {
    using enum GuardingMaster::Event;
    // 0x7F (toggle 0), then 0x7F again where toggle 1 was due, then in phase again.
    script = {0x7F, 0x7F, 0xFF, std::nullopt, std::nullopt, 0x7F};
    master.start(100ms, 2);
    bench.run_until(at_ms(550));
    ASSERT_EQ(events.size(), 3U);
    EXPECT_EQ(events[0].first, WrongToggle);
    // The reply to 200 is in phase again; 300 and 400 go unanswered, which 500 finds.
    EXPECT_EQ(events[1], (std::pair{NodeLost, at_ms(500)}));
    EXPECT_EQ(events[2].first, NodeResolved);
}

TEST_F(NodeGuardingMasterTest, BootUpMeansTheNextReplyHasToggleZero) {
    script = {0x7F, 0xFF};
    master.start(100ms, 2);
    bench.run_until(at_ms(150));
    bench.send("705#00");
    bench.run_until(at_ms(160));
    script = {0x7F};
    bench.run_until(at_ms(250));
    EXPECT_TRUE(events.empty());
    EXPECT_EQ(states, (std::vector{NmtState::PreOperational, NmtState::Initialising,
                                   NmtState::PreOperational}));
}

TEST(NodeGuardingEndToEnd, MasterGuardsARealSlaveThatLifeGuardsItself) {
    ServiceBench bench;
    ObjectDictionary od;
    add_node_guarding_objects(od);
    NmtSlave nmt(*bench.tester, kNode, {});
    std::vector<bool> slave_events;
    NodeGuarding slave(bench.loop, *bench.tester, od, kNode, {});
    nmt.on_state_change([&](NmtState state) { slave.set_nmt_state(state); });
    slave.on_life_guarding_event([&](bool occurred) { slave_events.push_back(occurred); });
    GuardingMaster master(bench.loop, *bench.device, kNode);
    std::vector<GuardingMaster::Event> master_events;
    master.on_event([&](GuardingMaster::Event event) { master_events.push_back(event); });
    bench.tester->on_receive([&](const can::Frame& frame) {
        nmt.on_frame(frame);
        slave.on_frame(frame);
    });
    bench.device->on_receive([&](const can::Frame& frame) { master.on_frame(frame); });
    nmt.boot();
    write_as(od, kGuardTimeIndex, 0, std::uint16_t{100});
    write_as(od, kLifeTimeFactorIndex, 0, std::uint8_t{3});

    master.start(100ms, 3);
    bench.run_until(at_ms(1000));
    nmt.apply(NmtCommand::Start);
    bench.run_until(at_ms(2000));
    EXPECT_EQ(master.remote_state(), NmtState::Operational);
    EXPECT_TRUE(master_events.empty());
    EXPECT_TRUE(slave_events.empty());

    master.stop(); // the master goes away: both sides notice
    bench.run_until(at_ms(3000));
    EXPECT_EQ(slave_events, std::vector<bool>{true});
}

} // namespace
} // namespace eposp::canopen
