#include "service_bench.hpp"
#include "eposp/canopen/heartbeat_consumer.hpp"
#include "eposp/canopen/heartbeat_producer.hpp"
#include "eposp/canopen/nmt_slave.hpp"

#include <gtest/gtest.h>
#include <optional>
#include <utility>
#include <vector>

namespace eposp::canopen {
namespace {

using namespace std::chrono_literals;
using testing::at_ms;
using testing::kFrameTime;
using testing::Sent;
using testing::ServiceBench;
using testing::write_as;

constexpr NodeId kNode = 5;

// ---------------------------------------------------------------------------------------------
// Producer

/// A slave with NMT and a heartbeat producer whose stored 0x1017 is `stored_ms`; reset
/// communication restores it.
class HeartbeatProducerTest : public ::testing::Test {
protected:
    void boot(std::uint16_t stored_ms) {
        add_heartbeat_producer_object(od);
        od.find(kProducerHeartbeatTimeIndex, 0)->default_value = encode(stored_ms);
        nmt.on_state_change([this](NmtState state) { producer.set_nmt_state(state); });
        bench.device->on_receive([this](const can::Frame& frame) { nmt.on_frame(frame); });
        nmt.boot();
    }
    /// Runs `fn` at `t` of virtual time.
    void at(core::TimePoint t, std::function<void()> fn) { bench.loop.at(t, std::move(fn)); }

    ServiceBench bench;
    ObjectDictionary od;
    NmtSlave nmt{*bench.device, kNode, {.application = {}, .communication = [this] {
                                            od.reset_to_defaults();
                                        }}};
    HeartbeatProducer producer{bench.loop, *bench.device, od, kNode};
};

TEST_F(HeartbeatProducerTest, FirstHeartbeatFollowsTheBootUpByOnePeriod) {
    boot(100);
    bench.run_until(at_ms(250));
    // CiA 301 7.2.8.3.2.2: the boot-up message is the first heartbeat.
    EXPECT_EQ(
        bench.device_frames(),
        (std::vector<Sent>{{at_ms(0), "705#00"}, {at_ms(100), "705#7F"}, {at_ms(200), "705#7F"}}));
}

TEST_F(HeartbeatProducerTest, CarriesTheNmtStateOfTheMoment) {
    boot(100);
    at(at_ms(150), [this] { nmt.apply(NmtCommand::Start); });
    at(at_ms(250), [this] { nmt.apply(NmtCommand::Stop); });
    bench.run_until(at_ms(400) + kFrameTime);
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "705#00"},
                                                        {at_ms(100), "705#7F"},
                                                        {at_ms(200), "705#05"},
                                                        {at_ms(300), "705#04"},
                                                        {at_ms(400), "705#04"}}));
}

TEST_F(HeartbeatProducerTest, ZeroMeansNoHeartbeat) {
    boot(0);
    bench.run_until(at_ms(1000));
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "705#00"}}));
    EXPECT_FALSE(producer.producing());
}

TEST_F(HeartbeatProducerTest, NewPeriodTakesEffectAtTheWrite) {
    boot(100);
    at(at_ms(150), [this] {
        EXPECT_EQ(write_as(od, kProducerHeartbeatTimeIndex, 0, std::uint16_t{30}), AbortCode::None);
    });
    bench.run_until(at_ms(245));
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "705#00"},
                                                        {at_ms(100), "705#7F"},
                                                        {at_ms(180), "705#7F"},
                                                        {at_ms(210), "705#7F"},
                                                        {at_ms(240), "705#7F"}}));
}

TEST_F(HeartbeatProducerTest, WritingZeroStopsAndANonZeroValueStartsIt) {
    boot(100);
    at(at_ms(150), [this] { write_as(od, kProducerHeartbeatTimeIndex, 0, std::uint16_t{0}); });
    at(at_ms(500), [this] { write_as(od, kProducerHeartbeatTimeIndex, 0, std::uint16_t{50}); });
    bench.run_until(at_ms(600) + kFrameTime);
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "705#00"},
                                                        {at_ms(100), "705#7F"},
                                                        {at_ms(550), "705#7F"},
                                                        {at_ms(600), "705#7F"}}));
}

TEST_F(HeartbeatProducerTest, ResetCommunicationRestartsFromTheBootUpWithTheStoredPeriod) {
    boot(100);
    at(at_ms(120), [this] { write_as(od, kProducerHeartbeatTimeIndex, 0, std::uint16_t{30}); });
    at(at_ms(165), [this] { nmt.apply(NmtCommand::ResetCommunication); });
    bench.run_until(at_ms(370));
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "705#00"},
                                                        {at_ms(100), "705#7F"},
                                                        {at_ms(150), "705#7F"},
                                                        {at_ms(165), "705#00"},
                                                        {at_ms(265), "705#7F"},
                                                        {at_ms(365), "705#7F"}}));
}

// ---------------------------------------------------------------------------------------------
// Consumer

constexpr std::uint32_t entry(NodeId node, std::uint16_t time_ms, std::uint8_t port = 0) {
    return std::uint32_t{port} << 24 | std::uint32_t{node} << 16 | time_ms;
}

/// The consumer on the device port, in pre-operational, with two 0x1016 entries; the tester
/// plays the producers.
class HeartbeatConsumerTest : public ::testing::Test {
protected:
    HeartbeatConsumerTest() {
        add_heartbeat_consumer_objects(od, 2);
        bench.device->on_receive([this](const can::Frame& frame) { consumer.on_frame(frame); });
        consumer.on_state_change(
            [this](NodeId node, NmtState state) { states.emplace_back(node, state); });
        consumer.on_timeout([this](NodeId node) { timeouts.emplace_back(node, bench.loop.now()); });
    }
    void configure(std::uint8_t sub_index, std::uint32_t value) {
        ASSERT_EQ(write_as(od, kConsumerHeartbeatTimeIndex, sub_index, value), AbortCode::None);
    }
    void start() { consumer.set_nmt_state(NmtState::PreOperational); }
    /// The tester sends `frame` at `t`; returns the time it arrives.
    core::TimePoint send_at(core::TimePoint t, std::string frame) {
        bench.run_until(t);
        bench.send(frame);
        bench.run_for(1ms);
        return bench.wire.events.back().end;
    }

    ServiceBench bench;
    ObjectDictionary od;
    std::vector<std::uint16_t> emergencies;
    HeartbeatConsumer consumer{bench.loop, od, [this](std::uint16_t code) {
                                   emergencies.push_back(code);
                               }};
    std::vector<std::pair<NodeId, NmtState>> states;
    std::vector<std::pair<NodeId, core::TimePoint>> timeouts;
};

TEST_F(HeartbeatConsumerTest, MonitoringStartsWithTheFirstHeartbeat) {
    configure(1, entry(6, 150));
    start();
    bench.run_until(at_ms(1000));
    EXPECT_TRUE(timeouts.empty()); // EPOS2 FW spec 8.2.13: nothing to miss before the first

    const core::TimePoint arrived = send_at(at_ms(1000), "706#7F");
    EXPECT_EQ(states, (std::vector<std::pair<NodeId, NmtState>>{{6, NmtState::PreOperational}}));
    EXPECT_EQ(consumer.remote_state(6), NmtState::PreOperational);
    bench.run_until(at_ms(2000));

    EXPECT_EQ(timeouts, (std::vector<std::pair<NodeId, core::TimePoint>>{{6, arrived + 150ms}}));
    EXPECT_EQ(emergencies, (std::vector<std::uint16_t>{0x8130}));
    EXPECT_EQ(consumer.remote_state(6), std::nullopt);
}

TEST_F(HeartbeatConsumerTest, EveryHeartbeatRestartsTheTime) {
    configure(1, entry(6, 150));
    start();
    core::TimePoint last{};
    for (int t = 0; t <= 1000; t += 140) {
        last = send_at(at_ms(t), "706#05");
    }
    bench.run_until(at_ms(2000));
    EXPECT_EQ(timeouts, (std::vector<std::pair<NodeId, core::TimePoint>>{{6, last + 150ms}}));
    EXPECT_EQ(states, (std::vector<std::pair<NodeId, NmtState>>{{6, NmtState::Operational}}));
}

TEST_F(HeartbeatConsumerTest, TracksTheRemoteStateIncludingItsBootUp) {
    configure(1, entry(6, 500));
    start();
    send_at(at_ms(0), "706#00");
    send_at(at_ms(100), "706#7F");
    send_at(at_ms(200), "706#7F");
    send_at(at_ms(300), "706#05");
    send_at(at_ms(400), "706#04");
    EXPECT_EQ(states, (std::vector<std::pair<NodeId, NmtState>>{{6, NmtState::Initialising},
                                                                {6, NmtState::PreOperational},
                                                                {6, NmtState::Operational},
                                                                {6, NmtState::Stopped}}));
    EXPECT_TRUE(timeouts.empty());
}

TEST_F(HeartbeatConsumerTest, ResumesWithTheNextHeartbeatAfterATimeout) {
    configure(1, entry(6, 100));
    start();
    send_at(at_ms(0), "706#05");
    bench.run_until(at_ms(500));
    const core::TimePoint again = send_at(at_ms(500), "706#05");
    bench.run_until(at_ms(1000));
    ASSERT_EQ(timeouts.size(), 2U);
    EXPECT_EQ(timeouts[1].second, again + 100ms);
    EXPECT_EQ(states, (std::vector<std::pair<NodeId, NmtState>>{{6, NmtState::Operational},
                                                                {6, NmtState::Operational}}));
    EXPECT_EQ(emergencies.size(), 2U);
}

TEST_F(HeartbeatConsumerTest, WatchesEachEntryWithItsOwnTime) {
    configure(1, entry(6, 100));
    configure(2, entry(7, 300));
    start();
    const core::TimePoint six = send_at(at_ms(0), "706#05");
    const core::TimePoint seven = send_at(at_ms(10), "707#05");
    bench.run_until(at_ms(1000));
    EXPECT_EQ(timeouts, (std::vector<std::pair<NodeId, core::TimePoint>>{{6, six + 100ms},
                                                                         {7, seven + 300ms}}));
}

TEST_F(HeartbeatConsumerTest, IgnoresFramesThatAreNotAHeartbeatOfAMonitoredNode) {
    configure(1, entry(6, 100));
    start();
    for (const char* frame :
         {"707#05", "706#0500", "706#", "706#R1", "706#85", "706#06", "00000706#05"}) {
        send_at(bench.loop.now(), frame);
    }
    bench.run_until(at_ms(1000));
    EXPECT_TRUE(states.empty());
    EXPECT_TRUE(timeouts.empty());
}

TEST_F(HeartbeatConsumerTest, EntryWithZeroTimeOrNodeIsUnused) {
    configure(1, entry(6, 0));
    configure(2, entry(0, 100));
    start();
    send_at(at_ms(0), "706#05");
    send_at(at_ms(0), "700#05");
    bench.run_until(at_ms(1000));
    EXPECT_TRUE(states.empty());
    EXPECT_TRUE(timeouts.empty());
}

TEST_F(HeartbeatConsumerTest, ChangedEntryWaitsForTheFirstHeartbeatAgain) {
    configure(1, entry(6, 100));
    start();
    send_at(at_ms(0), "706#05");
    bench.run_until(at_ms(50));
    configure(1, entry(7, 100));
    bench.run_until(at_ms(1000));
    EXPECT_TRUE(timeouts.empty());
    EXPECT_EQ(consumer.remote_state(6), std::nullopt);
    const core::TimePoint seven = send_at(at_ms(1000), "707#7F");
    bench.run_until(at_ms(2000));
    EXPECT_EQ(timeouts, (std::vector<std::pair<NodeId, core::TimePoint>>{{7, seven + 100ms}}));
}

TEST_F(HeartbeatConsumerTest, MonitorsInStoppedAndRestartsAfterAReset) {
    configure(1, entry(6, 100));
    start();
    consumer.set_nmt_state(NmtState::Stopped);
    send_at(at_ms(0), "706#05");
    bench.run_until(at_ms(50));
    consumer.set_nmt_state(NmtState::Initialising); // a reset: nothing is monitored
    bench.run_until(at_ms(500));
    EXPECT_TRUE(timeouts.empty());
    consumer.set_nmt_state(NmtState::PreOperational);
    EXPECT_EQ(consumer.remote_state(6), std::nullopt);
    const core::TimePoint again = send_at(at_ms(500), "706#05");
    bench.run_until(at_ms(1000));
    EXPECT_EQ(timeouts, (std::vector<std::pair<NodeId, core::TimePoint>>{{6, again + 100ms}}));
}

TEST_F(HeartbeatConsumerTest, IgnoresHeartbeatsWhileInitialising) {
    configure(1, entry(6, 100));
    send_at(at_ms(0), "706#05");
    bench.run_until(at_ms(500));
    EXPECT_TRUE(states.empty());
    EXPECT_TRUE(timeouts.empty());
}

TEST(HeartbeatConsumerPortCode, WatchesOnlyTheEntriesOfItsPort) {
    // EPOS P FW spec 10.11: bits 31..24 name the CAN port; the same node-ID may be on both.
    ServiceBench bench;
    ObjectDictionary od;
    add_heartbeat_consumer_objects(od, 128);
    ASSERT_EQ(write_as(od, kConsumerHeartbeatTimeIndex, 1, entry(6, 100, 2)), AbortCode::None);
    ASSERT_EQ(write_as(od, kConsumerHeartbeatTimeIndex, 128, entry(6, 100, 1)), AbortCode::None);
    HeartbeatConsumer external(bench.loop, od, {}, 2);
    std::vector<NodeId> lost;
    external.on_timeout([&](NodeId node) { lost.push_back(node); });
    bench.device->on_receive([&](const can::Frame& frame) { external.on_frame(frame); });
    external.set_nmt_state(NmtState::Operational);
    bench.send("706#05");
    bench.run_for(1s);
    EXPECT_EQ(lost, std::vector<NodeId>{6});
}

// CiA 301 7.5.2 (1016h) and the dictionary's checks, on a 0x1016 with two entries holding
// node 6 (150 ms) in sub-index 1.
struct ConsumerWriteCase {
    const char* what;
    std::uint8_t sub_index;
    Bytes data;
    AbortCode expected;
    friend void PrintTo(const ConsumerWriteCase& c, std::ostream* os) { *os << c.what; }
};

class HeartbeatConsumerObject : public ::testing::TestWithParam<ConsumerWriteCase> {};

TEST_P(HeartbeatConsumerObject, WriteIsCheckedAsCiA301Says) {
    const ConsumerWriteCase& c = GetParam();
    ObjectDictionary od;
    add_heartbeat_consumer_objects(od, 2);
    ASSERT_EQ(write_as(od, kConsumerHeartbeatTimeIndex, 1, entry(6, 150)), AbortCode::None);
    EXPECT_EQ(od.write(kConsumerHeartbeatTimeIndex, c.sub_index, c.data), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    HeartbeatCiA301, HeartbeatConsumerObject,
    ::testing::Values(
        ConsumerWriteCase{"second entry for the same node", 2, encode(entry(6, 200)),
                          AbortCode::ParameterIncompatibility},
        ConsumerWriteCase{"same node with time 0 is unused", 2, encode(entry(6, 0)),
                          AbortCode::None},
        ConsumerWriteCase{"another node", 2, encode(entry(7, 150)), AbortCode::None},
        ConsumerWriteCase{"node 0 is unused", 2, encode(entry(0, 150)), AbortCode::None},
        ConsumerWriteCase{"rewriting the entry itself", 1, encode(entry(6, 300)), AbortCode::None},
        ConsumerWriteCase{"no such entry", 3, encode(entry(7, 150)),
                          AbortCode::SubIndexDoesNotExist},
        ConsumerWriteCase{"number of entries is read-only", 0, encode(std::uint8_t{3}),
                          AbortCode::ReadOnly},
        ConsumerWriteCase{"too short", 2, {0x96, 0x00}, AbortCode::LengthTooLow}));

TEST(HeartbeatObjects, HaveTheirCiA301Defaults) {
    ObjectDictionary od;
    add_heartbeat_producer_object(od);
    add_heartbeat_consumer_objects(od, 2);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x1017, 0), 0);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1016, 0), 2);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1016, 1), 0U);
    EXPECT_EQ(od.find(0x1016, 2)->type, DataType::Unsigned32);
    EXPECT_TRUE(od.find(0x1017, 0)->persistent);
}

} // namespace
} // namespace eposp::canopen
