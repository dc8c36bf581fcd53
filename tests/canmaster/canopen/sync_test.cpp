#include "eposp/canopen/sync_consumer.hpp"
#include "eposp/canopen/sync_objects.hpp"
#include "eposp/canopen/sync_producer.hpp"
#include "service_bench.hpp"

#include <functional>
#include <gtest/gtest.h>
#include <optional>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::at_ms;
using testing::at_us;
using testing::kFrameTime;
using testing::Sent;
using testing::ServiceBench;
using testing::write_as;

constexpr std::uint32_t kGenerate = 0x4000'0080;

// ---------------------------------------------------------------------------------------------
// Producer

class SyncProducerTest : public ::testing::Test {
protected:
    SyncProducerTest() {
        add_sync_objects(od);
        producer.set_nmt_state(NmtState::PreOperational);
    }
    void write(std::uint16_t index, auto value) {
        ASSERT_EQ(write_as(od, index, 0, value), AbortCode::None);
    }
    std::vector<std::string> frames() const {
        std::vector<std::string> out;
        for (const Sent& sent : bench.device_frames()) {
            out.push_back(sent.frame);
        }
        return out;
    }

    ServiceBench bench;
    ObjectDictionary od;
    SyncProducer producer{bench.loop, *bench.device, od};
};

TEST_F(SyncProducerTest, SendsEveryCyclePeriodWhileGenerating) {
    write(kCobIdSyncIndex, kGenerate);
    write(kCommunicationCyclePeriodIndex, std::uint32_t{10'000});
    bench.run_until(at_ms(30) + kFrameTime);
    EXPECT_EQ(bench.device_frames(),
              (std::vector<Sent>{{at_ms(10), "080#"}, {at_ms(20), "080#"}, {at_ms(30), "080#"}}));
    EXPECT_TRUE(producer.producing());
}

TEST_F(SyncProducerTest, SendsNothingWithoutTheGenerateBitOrAPeriod) {
    write(kCommunicationCyclePeriodIndex, std::uint32_t{10'000});
    bench.run_until(at_ms(100));
    write(kCommunicationCyclePeriodIndex, std::uint32_t{0});
    write(kCobIdSyncIndex, kGenerate);
    bench.run_until(at_ms(200));
    EXPECT_TRUE(bench.device_frames().empty());
    EXPECT_FALSE(producer.producing());
}

TEST_F(SyncProducerTest, CounterStartsAtOneAndWrapsAfterTheOverflowValue) {
    write(kSyncCounterOverflowIndex, std::uint8_t{3});
    write(kCobIdSyncIndex, kGenerate);
    write(kCommunicationCyclePeriodIndex, std::uint32_t{1'000});
    bench.run_until(at_ms(7) + kFrameTime);
    EXPECT_EQ(frames(), (std::vector<std::string>{"080#01", "080#02", "080#03", "080#01", "080#02",
                                                  "080#03", "080#01"}));
}

TEST_F(SyncProducerTest, CounterWrapsAt240) {
    write(kSyncCounterOverflowIndex, std::uint8_t{240});
    write(kCobIdSyncIndex, kGenerate);
    write(kCommunicationCyclePeriodIndex, std::uint32_t{1'000});
    bench.run_until(at_ms(242) + kFrameTime);
    const auto sent = frames();
    ASSERT_EQ(sent.size(), 242U);
    EXPECT_EQ(sent[238], "080#EF");
    EXPECT_EQ(sent[239], "080#F0");
    EXPECT_EQ(sent[240], "080#01");
    EXPECT_EQ(sent[241], "080#02");
}

TEST_F(SyncProducerTest, NoSyncInStoppedAndLeavingItStartsAFreshCycle) {
    write(kSyncCounterOverflowIndex, std::uint8_t{5});
    write(kCobIdSyncIndex, kGenerate);
    write(kCommunicationCyclePeriodIndex, std::uint32_t{10'000});
    bench.run_until(at_ms(25));
    producer.set_nmt_state(NmtState::Stopped);
    bench.run_until(at_ms(55));
    producer.set_nmt_state(NmtState::Operational);
    bench.run_until(at_ms(75) + kFrameTime);
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(10), "080#01"},
                                                        {at_ms(20), "080#02"},
                                                        {at_ms(65), "080#01"},
                                                        {at_ms(75), "080#02"}}));
}

TEST_F(SyncProducerTest, PreOperationalToOperationalKeepsTheCycle) {
    write(kSyncCounterOverflowIndex, std::uint8_t{5});
    write(kCobIdSyncIndex, kGenerate);
    write(kCommunicationCyclePeriodIndex, std::uint32_t{10'000});
    bench.run_until(at_ms(15));
    producer.set_nmt_state(NmtState::Operational);
    bench.run_until(at_ms(20) + kFrameTime);
    EXPECT_EQ(bench.device_frames(),
              (std::vector<Sent>{{at_ms(10), "080#01"}, {at_ms(20), "080#02"}}));
}

TEST_F(SyncProducerTest, NewPeriodTakesEffectFromTheWrite) {
    write(kCobIdSyncIndex, kGenerate);
    write(kCommunicationCyclePeriodIndex, std::uint32_t{10'000});
    bench.run_until(at_ms(15));
    write(kCommunicationCyclePeriodIndex, std::uint32_t{2'000});
    bench.run_until(at_ms(19) + kFrameTime);
    EXPECT_EQ(bench.device_frames(),
              (std::vector<Sent>{{at_ms(10), "080#"}, {at_ms(17), "080#"}, {at_ms(19), "080#"}}));
}

TEST_F(SyncProducerTest, ResetStopsItUntilTheBootUp) {
    write(kCobIdSyncIndex, kGenerate);
    write(kCommunicationCyclePeriodIndex, std::uint32_t{10'000});
    bench.run_until(at_ms(15));
    producer.set_nmt_state(NmtState::Initialising);
    bench.run_until(at_ms(50));
    EXPECT_EQ(bench.device_frames().size(), 1U);
    producer.set_nmt_state(NmtState::PreOperational);
    bench.run_until(at_ms(60) + kFrameTime);
    EXPECT_EQ(bench.device_frames().back(), (Sent{at_ms(60), "080#"}));
}

TEST_F(SyncProducerTest, ExtendedIdentifierWithBit29) {
    write(kCobIdSyncIndex, std::uint32_t{0x6000'0080});
    write(kCommunicationCyclePeriodIndex, std::uint32_t{1'000});
    bench.run_until(at_us(1'500));
    EXPECT_EQ(frames(), std::vector<std::string>{"00000080#"});
}

TEST(SyncProducer, OnADeviceWithoutProducerObjectsStaysSilent) {
    // EPOS2 FW spec 8.1: no 0x1006 / 0x1019; a node on such a dictionary runs a producer anyway.
    ServiceBench bench;
    ObjectDictionary od;
    add_sync_objects(od, {.producer = false, .window = false});
    SyncProducer producer{bench.loop, *bench.device, od};
    producer.set_nmt_state(NmtState::Operational);
    bench.run_for(100ms);
    EXPECT_TRUE(bench.device_frames().empty());
}

TEST_F(SyncProducerTest, HandsItsOwnSyncToTheNodesConsumer) {
    SyncConsumer consumer(bench.loop, od, {});
    consumer.set_nmt_state(NmtState::PreOperational);
    std::vector<std::optional<std::uint8_t>> counters;
    consumer.on_sync([&](const SyncEvent& event) { counters.push_back(event.counter); });
    producer.on_sent([&](const can::Frame& frame) { consumer.on_frame(frame); });
    write(kSyncCounterOverflowIndex, std::uint8_t{2});
    write(kCobIdSyncIndex, kGenerate);
    write(kCommunicationCyclePeriodIndex, std::uint32_t{1'000});
    bench.run_until(at_us(3'500));
    EXPECT_EQ(counters, (std::vector<std::optional<std::uint8_t>>{1, 2, 1}));
}

// CiA 301 7.5.2 (1005h, 1006h, 1007h, 1019h) and the EPOS P's ranges (FW spec 10.6, 10.7), on
// objects that start at their defaults; `setup` writes what the case needs first.
struct SyncWriteCase {
    const char* what;
    std::function<void(ObjectDictionary&)> setup;
    std::uint16_t index;
    Bytes data;
    AbortCode expected;
    friend void PrintTo(const SyncWriteCase& c, std::ostream* os) { *os << c.what; }
};

void generating(ObjectDictionary& od) {
    od.set_as(kCobIdSyncIndex, 0, kGenerate);
}
void cycling(ObjectDictionary& od) {
    od.set_as(kCommunicationCyclePeriodIndex, 0, std::uint32_t{1'000});
}

const std::vector<SyncWriteCase> kSyncWrites = {
    {"generate", {}, 0x1005, encode(kGenerate), AbortCode::None},
    {"another identifier while not generating",
     {},
     0x1005,
     encode(std::uint32_t{0x81}),
     AbortCode::None},
    {"another identifier while generating", generating, 0x1005, encode(std::uint32_t{0x4000'0081}),
     AbortCode::InvalidValue},
    {"29-bit identifier while generating", generating, 0x1005, encode(std::uint32_t{0x6000'0080}),
     AbortCode::InvalidValue},
    {"same identifier while generating, bit 31 ignored", generating, 0x1005,
     encode(std::uint32_t{0xC000'0080}), AbortCode::None},
    {"stop generating with another identifier", generating, 0x1005,
     encode(std::uint32_t{0x0000'0081}), AbortCode::None},
    {"reserved identifier (NMT error control)",
     {},
     0x1005,
     encode(std::uint32_t{0x705}),
     AbortCode::InvalidValue},
    {"reserved identifier (SDO)",
     {},
     0x1005,
     encode(std::uint32_t{0x605}),
     AbortCode::InvalidValue},
    {"bits 11..28 of an 11-bit identifier",
     {},
     0x1005,
     encode(std::uint32_t{0x0000'0880}),
     AbortCode::InvalidValue},
    {"29-bit identifier", {}, 0x1005, encode(std::uint32_t{0x2000'0705}), AbortCode::None},
    {"period", {}, 0x1006, encode(std::uint32_t{1'000}), AbortCode::None},
    {"period 0", cycling, 0x1006, encode(std::uint32_t{0}), AbortCode::None},
    {"period below the EPOS P's minimum",
     {},
     0x1006,
     encode(std::uint32_t{999}),
     AbortCode::ValueTooLow},
    {"window", {}, 0x1007, encode(std::uint32_t{500}), AbortCode::None},
    {"window 0", {}, 0x1007, encode(std::uint32_t{0}), AbortCode::None},
    {"window below the EPOS P's minimum",
     {},
     0x1007,
     encode(std::uint32_t{499}),
     AbortCode::ValueTooLow},
    {"counter overflow 0", {}, 0x1019, encode(std::uint8_t{0}), AbortCode::None},
    {"counter overflow 1 is reserved",
     {},
     0x1019,
     encode(std::uint8_t{1}),
     AbortCode::InvalidValue},
    {"counter overflow 2", {}, 0x1019, encode(std::uint8_t{2}), AbortCode::None},
    {"counter overflow 240", {}, 0x1019, encode(std::uint8_t{240}), AbortCode::None},
    {"counter overflow 241 is reserved",
     {},
     0x1019,
     encode(std::uint8_t{241}),
     AbortCode::InvalidValue},
    {"counter overflow while the period is set", cycling, 0x1019, encode(std::uint8_t{10}),
     AbortCode::DeviceState},
    {"counter overflow too long", {}, 0x1019, encode(std::uint16_t{10}), AbortCode::LengthTooHigh},
    {"period too short", {}, 0x1006, encode(std::uint16_t{1000}), AbortCode::LengthTooLow},
};

class SyncObjectWrite : public ::testing::TestWithParam<SyncWriteCase> {};

TEST_P(SyncObjectWrite, IsCheckedAsCiA301AndTheManualSay) {
    const SyncWriteCase& c = GetParam();
    ObjectDictionary od;
    add_sync_objects(od, {.min_cycle_period_us = 1'000, .min_window_length_us = 500});
    if (c.setup) {
        c.setup(od);
    }
    const Bytes before = od.get(c.index, 0);
    EXPECT_EQ(od.write(c.index, 0, c.data), c.expected);
    EXPECT_EQ(od.get(c.index, 0), c.expected == AbortCode::None ? c.data : before);
}

INSTANTIATE_TEST_SUITE_P(SyncCiA301, SyncObjectWrite, ::testing::ValuesIn(kSyncWrites));

TEST(SyncObjects, ConsumerOnlyDeviceHasJust1005AndRefusesTheGenerateBit) {
    // EPOS2 FW spec 8.1: 0x1005 only.
    ObjectDictionary od;
    add_sync_objects(od, {.producer = false, .window = false});
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1005, 0), 0x80U);
    EXPECT_EQ(od.find(0x1006), nullptr);
    EXPECT_EQ(od.find(0x1007), nullptr);
    EXPECT_EQ(od.find(0x1019), nullptr);
    EXPECT_EQ(write_as(od, 0x1005, 0, kGenerate), AbortCode::InvalidValue);
}

TEST(SyncObjects, HaveTheirCiA301Defaults) {
    ObjectDictionary od;
    add_sync_objects(od);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1005, 0), 0x80U);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1006, 0), 0U);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1007, 0), 0U);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1019, 0), 0);
}

// ---------------------------------------------------------------------------------------------
// Consumer

class SyncConsumerTest : public ::testing::Test {
protected:
    void build(SyncObjectOptions options) {
        add_sync_objects(od, options);
        consumer.emplace(bench.loop, od,
                         [this](std::uint16_t code) { emergencies.push_back(code); });
        consumer->set_nmt_state(NmtState::Operational);
        consumer->on_sync([this](const SyncEvent& event) {
            syncs.push_back({event.counter, event.window, bench.loop.now()});
        });
        consumer->on_window_closed([this] { closed.push_back(bench.loop.now()); });
        bench.device->on_receive([this](const can::Frame& frame) { consumer->on_frame(frame); });
    }
    /// Sends a frame from the tester and returns when it arrived.
    core::TimePoint send(std::string_view frame) {
        bench.send(frame);
        bench.run_for(1ms);
        return bench.wire.events.back().end;
    }

    struct Seen {
        std::optional<std::uint8_t> counter;
        core::Duration window;
        core::TimePoint at;
        friend bool operator==(const Seen&, const Seen&) = default;
    };

    ServiceBench bench;
    ObjectDictionary od;
    std::vector<std::uint16_t> emergencies;
    std::optional<SyncConsumer> consumer;
    std::vector<Seen> syncs;
    std::vector<core::TimePoint> closed;
};

TEST_F(SyncConsumerTest, TellsOfEverySyncWithItsCounter) {
    build({.producer = false, .window = false}); // an EPOS2: no 0x1019, both forms accepted
    const core::TimePoint first = send("080#");
    const core::TimePoint second = send("080#07");
    EXPECT_EQ(syncs, (std::vector<Seen>{{std::nullopt, 0ns, first}, {7, 0ns, second}}));
    EXPECT_TRUE(emergencies.empty());
}

TEST_F(SyncConsumerTest, SyncOfTheWrongLengthRaisesAnEmergency) {
    build({});
    ASSERT_EQ(write_as(od, kSyncCounterOverflowIndex, 0, std::uint8_t{10}), AbortCode::None);
    send("080#");
    send("080#0102"); // the same error, still present: no second emergency
    const core::TimePoint good = send("080#03");
    EXPECT_EQ(syncs, (std::vector<Seen>{{3, 0ns, good}}));
    EXPECT_EQ(emergencies, (std::vector<std::uint16_t>{0x8240}));

    ASSERT_EQ(write_as(od, kSyncCounterOverflowIndex, 0, std::uint8_t{0}), AbortCode::None);
    send("080#03");
    EXPECT_EQ(emergencies.size(), 2U) << "a new error after the SYNC of the right length";
}

TEST_F(SyncConsumerTest, WindowOpensWithEachSyncAndClosesAfterItsLength) {
    build({});
    ASSERT_EQ(write_as(od, kSynchronousWindowLengthIndex, 0, std::uint32_t{2'000}),
              AbortCode::None);
    EXPECT_FALSE(consumer->window_open());
    const core::TimePoint arrived = send("080#");
    EXPECT_EQ(syncs, (std::vector<Seen>{{std::nullopt, 2ms, arrived}}));
    EXPECT_TRUE(consumer->window_open());
    bench.run_until(arrived + 2ms - 1ns);
    EXPECT_TRUE(consumer->window_open());
    bench.run_until(arrived + 2ms);
    EXPECT_FALSE(consumer->window_open());
    EXPECT_EQ(closed, std::vector<core::TimePoint>{arrived + 2ms});
}

TEST_F(SyncConsumerTest, WithoutAWindowSynchronousPdosMayAlwaysGo) {
    build({});
    EXPECT_TRUE(consumer->window_open());
    send("080#");
    bench.run_for(1s);
    EXPECT_TRUE(consumer->window_open());
    EXPECT_TRUE(closed.empty());
}

TEST_F(SyncConsumerTest, ListensOnlyInPreOperationalAndOperational) {
    build({});
    consumer->set_nmt_state(NmtState::Stopped);
    send("080#");
    consumer->set_nmt_state(NmtState::Initialising);
    send("080#");
    consumer->set_nmt_state(NmtState::PreOperational);
    send("080#");
    EXPECT_EQ(syncs.size(), 1U);
}

TEST_F(SyncConsumerTest, TakesOnlyFramesWithItsCobId) {
    build({});
    for (const char* frame : {"081#", "080#R", "00000080#"}) {
        send(frame);
    }
    EXPECT_TRUE(syncs.empty());
    ASSERT_EQ(write_as(od, kCobIdSyncIndex, 0, std::uint32_t{0x2000'0080}), AbortCode::None);
    send("00000080#");
    send("080#");
    EXPECT_EQ(syncs.size(), 1U);
}

TEST(SyncEndToEnd, ConsumerOnAnotherNodeSeesTheCounterWrap) {
    ServiceBench bench;
    ObjectDictionary producer_od;
    ObjectDictionary consumer_od;
    add_sync_objects(producer_od);
    add_sync_objects(consumer_od);
    SyncProducer producer(bench.loop, *bench.device, producer_od);
    SyncConsumer consumer(bench.loop, consumer_od, {});
    bench.tester->on_receive([&](const can::Frame& frame) { consumer.on_frame(frame); });
    std::vector<std::uint8_t> counters;
    consumer.on_sync([&](const SyncEvent& event) { counters.push_back(event.counter.value()); });
    for (ObjectDictionary* od : {&producer_od, &consumer_od}) {
        ASSERT_EQ(write_as(*od, kSyncCounterOverflowIndex, 0, std::uint8_t{2}), AbortCode::None);
    }
    ASSERT_EQ(write_as(producer_od, kCobIdSyncIndex, 0, kGenerate), AbortCode::None);
    ASSERT_EQ(write_as(producer_od, kCommunicationCyclePeriodIndex, 0, std::uint32_t{1'000}),
              AbortCode::None);
    producer.set_nmt_state(NmtState::Operational);
    consumer.set_nmt_state(NmtState::Operational);
    bench.run_until(at_us(5'500));
    EXPECT_EQ(counters, (std::vector<std::uint8_t>{1, 2, 1, 2, 1}));
}

} // namespace
} // namespace eposp::canopen
