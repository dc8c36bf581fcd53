#include "eposp/canopen/emcy_consumer.hpp"
#include "eposp/canopen/emcy_producer.hpp"
#include "eposp/canopen/error_history.hpp"
#include "service_bench.hpp"

#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>
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

/// An EPOS2-like node-5 EMCY producer (five history entries) with 0x1015, in pre-operational.
class EmcyProducerTest : public ::testing::Test {
protected:
    EmcyProducerTest() {
        add_error_objects(od, kEpos2ErrorHistoryEntries);
        add_emcy_objects(od, kNode);
        emcy.set_nmt_state(NmtState::PreOperational);
    }
    std::uint8_t error_register() const { return od.get_as<std::uint8_t>(0x1001, 0); }
    std::vector<std::uint32_t> history() { return ErrorHistory(od).entries(); }
    void at(core::TimePoint t, std::function<void()> fn) { bench.loop.at(t, std::move(fn)); }

    ServiceBench bench;
    ObjectDictionary od;
    EmcyProducer emcy{bench.loop, *bench.device, od};
};

TEST_F(EmcyProducerTest, ErrorEventSendsCodeRegisterAndManufacturerBytes) {
    emcy.raise(0x8130, error_register::kCommunication, {1, 2, 3, 4, 5});
    bench.run_for(1ms);
    // CiA 301 7.2.7.3.1, EPOS2 FW spec table 4-10: code little-endian, register, 5 bytes. The
    // register has the generic bit with every error (CiA 301 7.5.2.2).
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "085#3081110102030405"}}));
    EXPECT_EQ(error_register(), 0x11);
    EXPECT_EQ(history(), std::vector<std::uint32_t>{0x8130});
    EXPECT_TRUE(emcy.active(0x8130));
}

TEST_F(EmcyProducerTest, ActiveErrorRaisedAgainSendsNothing) {
    emcy.raise(0x8130, error_register::kCommunication);
    emcy.raise(0x8130, error_register::kCommunication);
    bench.run_for(1ms);
    EXPECT_EQ(bench.device_frames().size(), 1U); // EPOS2 FW spec 4.1: once per error event
    EXPECT_EQ(history().size(), 1U);
}

TEST_F(EmcyProducerTest, ErrorThatGoesAwaySendsErrorResetWithTheRemainingRegister) {
    emcy.raise(0x2310, error_register::kCurrent);
    emcy.raise(0x8130, error_register::kCommunication);
    EXPECT_EQ(error_register(), 0x13);
    emcy.clear(0x2310);
    EXPECT_EQ(error_register(), 0x11);
    emcy.clear(0x2310); // no longer active: nothing
    emcy.clear(0x8130, {0xAA, 0, 0, 0, 0xBB});
    EXPECT_EQ(error_register(), 0x00);
    bench.run_for(1ms);
    std::vector<std::string> frames;
    for (const Sent& sent : bench.device_frames()) {
        frames.push_back(sent.frame);
    }
    EXPECT_EQ(frames, (std::vector<std::string>{"085#1023030000000000", "085#3081130000000000",
                                                "085#0000110000000000", "085#000000AA000000BB"}));
    EXPECT_EQ(history(), (std::vector<std::uint32_t>{0x8130, 0x2310}));
}

TEST_F(EmcyProducerTest, ClearAllSendsOneErrorReset) {
    emcy.raise(0x2310, error_register::kCurrent);
    emcy.raise(0x3210, error_register::kVoltage);
    emcy.clear_all();
    emcy.clear_all();
    bench.run_for(1ms);
    EXPECT_EQ(bench.device_frames().size(), 3U);
    EXPECT_EQ(bench.device_frames().back().frame, "085#0000000000000000");
    EXPECT_FALSE(emcy.active(0x2310));
}

TEST_F(EmcyProducerTest, InhibitTimeSpacesEmcysAndKeepsTheirOrder) {
    ASSERT_EQ(write_as(od, kInhibitTimeEmcyIndex, 0, std::uint16_t{50}), AbortCode::None);
    at(at_ms(0), [this] { emcy.raise(0x2310, error_register::kCurrent); });
    at(at_ms(1), [this] { emcy.raise(0x3210, error_register::kVoltage); });
    at(at_ms(2), [this] { emcy.clear(0x2310); });
    at(at_ms(30), [this] { emcy.raise(0x4210, error_register::kTemperature); });
    bench.run_until(at_ms(30) + kFrameTime);
    // 0x1015 counts in 100 µs: 5 ms between EMCYs; one after a quiet spell goes at once.
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "085#1023030000000000"},
                                                        {at_ms(5), "085#1032070000000000"},
                                                        {at_ms(10), "085#0000050000000000"},
                                                        {at_ms(30), "085#10420D0000000000"}}));
}

TEST_F(EmcyProducerTest, PendingEmcysBeyondTheQueueAreLostButRecorded) {
    ASSERT_EQ(write_as(od, kInhibitTimeEmcyIndex, 0, std::uint16_t{10}), AbortCode::None);
    for (std::uint16_t code = 0x1000; code < 0x1000 + 20; ++code) {
        emcy.raise(code, error_register::kGeneric);
    }
    bench.run_for(1s);
    EXPECT_EQ(bench.device_frames().size(), 1 + EmcyProducer::kMaxPending);
    EXPECT_EQ(history().size(), kEpos2ErrorHistoryEntries);
}

TEST(EmcyProducerQueue, AnEmcyTheFullTransmitQueueRefusedLeavesOnceThereIsRoom) {
    ServiceBench bench;
    const auto port = bench.bus.connect("small", 2);
    ObjectDictionary od;
    add_error_objects(od, kEpos2ErrorHistoryEntries);
    add_emcy_objects(od, kNode);
    EmcyProducer emcy{bench.loop, *port, od};
    emcy.set_nmt_state(NmtState::PreOperational);
    const can::Frame filler = *can::parse_candump_frame("185#0102030405060708");
    std::size_t taken = 0;
    while (port->send(filler) == can::SendStatus::Queued) {
        ++taken;
    }
    emcy.raise(0x8110, error_register::kCommunication);
    emcy.raise(0x81FF, error_register::kCommunication);
    bench.run_for(10ms);

    const std::vector<Sent> sent = bench.sent_by("small");
    ASSERT_EQ(sent.size(), taken + 2);
    EXPECT_EQ(sent[taken].frame, "085#1081110000000000");
    EXPECT_EQ(sent[taken + 1].frame, "085#FF81110000000000");
    // Offered again every kQueueRetry: the first leaves within one retry of the queue's room.
    EXPECT_LE(sent[taken].at - sent[taken - 1].at, EmcyProducer::kQueueRetry + kFrameTime);
}

TEST_F(EmcyProducerTest, StoppedSendsNoEmcyButRecordsTheError) {
    emcy.set_nmt_state(NmtState::Stopped);
    emcy.raise(0x8130, error_register::kCommunication);
    bench.run_for(1ms);
    EXPECT_TRUE(bench.device_frames().empty()); // EPOS2 FW spec 7.3.5
    EXPECT_EQ(error_register(), 0x11);
    EXPECT_EQ(history(), std::vector<std::uint32_t>{0x8130});
    emcy.set_nmt_state(NmtState::Operational);
    bench.run_for(1ms);
    EXPECT_TRUE(bench.device_frames().empty());
}

TEST_F(EmcyProducerTest, ErrorThatEndsWhileNoEmcyMaySendItsResetOnceOneMay) {
    emcy.raise(0x8130, error_register::kCommunication);
    emcy.set_nmt_state(NmtState::Initialising);
    emcy.clear(0x8130);
    EXPECT_EQ(error_register(), 0x00);
    emcy.set_nmt_state(NmtState::PreOperational);
    bench.run_for(1ms);
    const std::vector<Sent> sent = bench.device_frames();
    ASSERT_EQ(sent.size(), 2U);
    EXPECT_EQ(sent[0].frame, "085#3081110000000000");
    EXPECT_EQ(sent[1].frame, "085#0000000000000000");
}

TEST_F(EmcyProducerTest, InvalidCobIdSendsNothingAndANewOneIsUsed) {
    ASSERT_EQ(write_as(od, kCobIdEmcyIndex, 0, std::uint32_t{0x8000'0085}), AbortCode::None);
    emcy.raise(0x2310, error_register::kCurrent);
    ASSERT_EQ(write_as(od, kCobIdEmcyIndex, 0, std::uint32_t{0x8000'0090}), AbortCode::None);
    ASSERT_EQ(write_as(od, kCobIdEmcyIndex, 0, std::uint32_t{0x0000'0090}), AbortCode::None);
    emcy.raise(0x3210, error_register::kVoltage);
    ASSERT_EQ(write_as(od, kCobIdEmcyIndex, 0, std::uint32_t{0x8000'0090}), AbortCode::None);
    ASSERT_EQ(write_as(od, kCobIdEmcyIndex, 0, std::uint32_t{0x2000'0090}), AbortCode::None);
    emcy.clear_all();
    bench.run_for(1ms);
    // Both are queued at 0: the second follows the first on the wire.
    const core::TimePoint second = testing::after_intermission(bench.wire.events.at(0).end);
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{at_ms(0), "090#1032070000000000"},
                                                        {second, "00000090#0000000000000000"}}));
}

TEST_F(EmcyProducerTest, ResetDropsPendingEmcysAndKeepsActiveErrorsInTheRegister) {
    ASSERT_EQ(write_as(od, kInhibitTimeEmcyIndex, 0, std::uint16_t{100}), AbortCode::None);
    emcy.raise(0x2310, error_register::kCurrent);
    emcy.raise(0x3210, error_register::kVoltage);
    emcy.set_nmt_state(NmtState::Initialising);
    od.reset_to_defaults();
    emcy.set_nmt_state(NmtState::PreOperational);
    bench.run_for(1s);
    EXPECT_EQ(bench.device_frames().size(), 1U);
    EXPECT_EQ(error_register(), 0x07);
}

// ---------------------------------------------------------------------------------------------
// Objects

struct EmcyWriteCase {
    const char* what;
    std::uint32_t before; ///< 0x1014 before the write
    Bytes data;
    AbortCode expected;
    friend void PrintTo(const EmcyWriteCase& c, std::ostream* os) { *os << c.what; }
};

class EmcyCobIdWrite : public ::testing::TestWithParam<EmcyWriteCase> {};

TEST_P(EmcyCobIdWrite, IsCheckedAsCiA301Says) {
    const EmcyWriteCase& c = GetParam();
    ObjectDictionary od;
    add_emcy_objects(od, kNode);
    od.set_as(kCobIdEmcyIndex, 0, c.before);
    EXPECT_EQ(od.write(kCobIdEmcyIndex, 0, c.data), c.expected);
    EXPECT_EQ(od.get(kCobIdEmcyIndex, 0),
              c.expected == AbortCode::None ? c.data : encode(c.before));
}

constexpr std::uint32_t kValid = 0x85;
constexpr std::uint32_t kInvalid = 0x8000'0085;

INSTANTIATE_TEST_SUITE_P(
    EmcyCiA301, EmcyCobIdWrite,
    ::testing::Values(EmcyWriteCase{"same value", kValid, encode(kValid), AbortCode::None},
                      EmcyWriteCase{"new identifier while valid", kValid,
                                    encode(std::uint32_t{0x86}), AbortCode::InvalidValue},
                      EmcyWriteCase{"29-bit while valid", kValid,
                                    encode(std::uint32_t{0x2000'0085}), AbortCode::InvalidValue},
                      EmcyWriteCase{"make invalid", kValid, encode(kInvalid), AbortCode::None},
                      EmcyWriteCase{"invalid without an identifier", kValid,
                                    encode(std::uint32_t{0x8000'0000}), AbortCode::None},
                      EmcyWriteCase{"new identifier while invalid", kInvalid,
                                    encode(std::uint32_t{0x90}), AbortCode::None},
                      EmcyWriteCase{"29-bit while invalid", kInvalid,
                                    encode(std::uint32_t{0x2000'0705}), AbortCode::None},
                      EmcyWriteCase{"reserved identifier (NMT)", kInvalid,
                                    encode(std::uint32_t{0x000}), AbortCode::InvalidValue},
                      EmcyWriteCase{"reserved identifier (LSS)", kInvalid,
                                    encode(std::uint32_t{0x7E5}), AbortCode::InvalidValue},
                      EmcyWriteCase{"bits 11..28 of an 11-bit identifier", kInvalid,
                                    encode(std::uint32_t{0x0001'0085}), AbortCode::InvalidValue},
                      EmcyWriteCase{"too short", kValid, {0x85, 0, 0}, AbortCode::LengthTooLow}));

TEST(EmcyObjects, HaveTheirDefaultsAndInhibitTimeIsOptional) {
    ObjectDictionary od;
    add_emcy_objects(od, 9);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1014, 0), 0x89U); // EPOS2 FW spec 8.2.12
    EXPECT_EQ(od.get_as<std::uint16_t>(0x1015, 0), 0);
    EXPECT_EQ(write_as(od, 0x1015, 0, std::uint16_t{1000}), AbortCode::None);
    EXPECT_EQ(write_as(od, 0x1015, 0, std::uint32_t{1000}), AbortCode::LengthTooHigh);

    ObjectDictionary epos2;
    add_emcy_objects(epos2, 9, false);
    EXPECT_EQ(epos2.find(0x1015), nullptr);
}

// ---------------------------------------------------------------------------------------------
// Error register and error history

class EmcyErrorHistory : public ::testing::Test {
protected:
    EmcyErrorHistory() { add_error_objects(od, kEpos2ErrorHistoryEntries); }
    std::uint8_t count() const { return od.get_as<std::uint8_t>(0x1003, 0); }

    ObjectDictionary od;
    ErrorHistory history{od};
};

TEST_F(EmcyErrorHistory, NewestIsAtSubIndexOneAndTheOldestDropsOff) {
    for (std::uint32_t code = 1; code <= 7; ++code) {
        history.record(code);
    }
    // EPOS2 FW spec 8.2.3: five entries, newest at sub-index 1.
    EXPECT_EQ(count(), 5);
    for (std::uint8_t sub = 1; sub <= 5; ++sub) {
        Bytes value;
        ASSERT_EQ(od.read(0x1003, sub, value), AbortCode::None);
        EXPECT_EQ(decode<std::uint32_t>(value), 8U - sub);
    }
    EXPECT_EQ(history.entries(), (std::vector<std::uint32_t>{7, 6, 5, 4, 3}));
}

TEST_F(EmcyErrorHistory, WritingZeroEmptiesIt) {
    history.record(0x8130);
    history.record(0x2310);
    EXPECT_EQ(write_as(od, 0x1003, 0, std::uint8_t{0}), AbortCode::None);
    EXPECT_EQ(count(), 0);
    EXPECT_TRUE(history.entries().empty());
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1003, 1), 0U);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1003, 2), 0U);
    history.record(0x3210);
    EXPECT_EQ(history.entries(), std::vector<std::uint32_t>{0x3210});
}

TEST_F(EmcyErrorHistory, DeviceMayClearItAndSetTheRegister) {
    history.record(0x6381);
    history.set_error_register(error_register::kGeneric | error_register::kManufacturer);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1001, 0), 0x81);
    EXPECT_EQ(history.error_register(), 0x81);
    history.clear();
    EXPECT_EQ(count(), 0);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1003, 1), 0U);
}

// CiA 301 7.5.2.2: whoever sets the register (the EMCY producer, a device's own error list),
// any error bit comes with the generic one; no error, no bit.
TEST_F(EmcyErrorHistory, RegisterHasTheGenericBitWithEveryError) {
    history.set_error_register(error_register::kCommunication);
    EXPECT_EQ(history.error_register(), 0x11);
    history.set_error_register(0);
    EXPECT_EQ(history.error_register(), 0x00);
}

// An EDS's own 0x1003 (plain data, imported) is kept and gets the rule of sub-index 0.
TEST(EmcyErrorHistoryOfAnEds, KeepsItsEntriesAndTakesTheRuleOfSubIndexZero) {
    ObjectDictionary od;
    od.add_object(0x1003, "Error History", ObjectCode::Array);
    for (std::uint8_t sub = 1; sub <= 3; ++sub) {
        od.add_sub(0x1003, sub, "Entry", DataType::Unsigned32, Access::ReadOnly,
                   encode(std::uint32_t{0}));
    }
    od.find(0x1003, 0)->access = Access::ReadWrite;
    add_error_objects(od, kEpos2ErrorHistoryEntries);
    ASSERT_NE(od.find(0x1001), nullptr);
    ErrorHistory history(od);
    for (std::uint32_t code = 1; code <= 4; ++code) {
        history.record(code);
    }
    EXPECT_EQ(history.entries(), (std::vector<std::uint32_t>{4, 3, 2})) << "three entries";
    EXPECT_EQ(write_as(od, 0x1003, 0, std::uint8_t{1}), AbortCode::InvalidValue);
    EXPECT_EQ(write_as(od, 0x1003, 0, std::uint8_t{0}), AbortCode::None);
    EXPECT_TRUE(history.entries().empty());
}

struct HistoryWriteCase {
    const char* what;
    std::uint16_t index;
    std::uint8_t sub_index;
    Bytes data;
    AbortCode expected;
    friend void PrintTo(const HistoryWriteCase& c, std::ostream* os) { *os << c.what; }
};

class EmcyErrorObjectWrite : public ::testing::TestWithParam<HistoryWriteCase> {};

TEST_P(EmcyErrorObjectWrite, IsRefusedWithTheCodeCiA301Gives) {
    const HistoryWriteCase& c = GetParam();
    ObjectDictionary od;
    add_error_objects(od, kEpos2ErrorHistoryEntries);
    ErrorHistory(od).record(0x8130);
    EXPECT_EQ(od.write(c.index, c.sub_index, c.data), c.expected);
    EXPECT_EQ(ErrorHistory(od).entries(), std::vector<std::uint32_t>{0x8130});
}

INSTANTIATE_TEST_SUITE_P(
    EmcyCiA301, EmcyErrorObjectWrite,
    ::testing::Values(
        HistoryWriteCase{"number of errors other than 0", 0x1003, 0, {1}, AbortCode::InvalidValue},
        HistoryWriteCase{"number of errors 255", 0x1003, 0, {255}, AbortCode::InvalidValue},
        HistoryWriteCase{"an entry", 0x1003, 1, {0, 0, 0, 0}, AbortCode::ReadOnly},
        HistoryWriteCase{
            "beyond the capacity", 0x1003, 6, {0, 0, 0, 0}, AbortCode::SubIndexDoesNotExist},
        HistoryWriteCase{"number of errors too long", 0x1003, 0, {0, 0}, AbortCode::LengthTooHigh},
        HistoryWriteCase{"error register", 0x1001, 0, {0}, AbortCode::ReadOnly}));

TEST(EmcyErrorObjects, HaveTheCapacityOfEachManual) {
    ObjectDictionary epos_p;
    add_error_objects(epos_p, kEposPErrorHistoryEntries);
    EXPECT_NE(epos_p.find(0x1003, 16), nullptr); // EPOS P FW spec 10.4
    EXPECT_EQ(epos_p.find(0x1003, 17), nullptr);
    EXPECT_EQ(epos_p.get_as<std::uint8_t>(0x1003, 0), 0);
    EXPECT_EQ(epos_p.find(0x1003, 0)->access, Access::ReadWrite);
    EXPECT_EQ(epos_p.find(0x1001, 0)->access, Access::ReadOnly);

    ObjectDictionary none;
    EXPECT_THROW(add_error_objects(none, 0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Consumer

class EmcyConsumerTest : public ::testing::Test {
protected:
    EmcyConsumerTest() {
        consumer.set_nmt_state(NmtState::Operational);
        consumer.on_emergency([this](const Emergency& emergency) { seen.push_back(emergency); });
        bench.device->on_receive([this](const can::Frame& frame) { consumer.on_frame(frame); });
    }
    void send(std::string_view frame) {
        bench.send(frame);
        bench.run_for(1ms);
    }

    ServiceBench bench;
    EmcyConsumer consumer;
    std::vector<Emergency> seen;
};

TEST_F(EmcyConsumerTest, TellsOfEveryEmcyWithItsSender) {
    send("086#3081100102030405");
    send("0FF#0000000000000000");
    EXPECT_EQ(seen, (std::vector<Emergency>{{6, 0x8130, 0x10, {1, 2, 3, 4, 5}},
                                            {127, 0x0000, 0x00, {0, 0, 0, 0, 0}}}));
}

TEST_F(EmcyConsumerTest, IgnoresFramesThatAreNotAnEmcy) {
    for (const char* frame : {"080#", "080#0000000000000000", "100#3081100102030405",
                              "086#30811001020304", "086#R8", "00000086#3081100102030405"}) {
        send(frame);
    }
    EXPECT_TRUE(seen.empty());
}

TEST_F(EmcyConsumerTest, ListensOnlyInPreOperationalAndOperational) {
    consumer.set_nmt_state(NmtState::Stopped);
    send("086#3081100000000000");
    consumer.set_nmt_state(NmtState::PreOperational);
    send("086#3081100000000000");
    EXPECT_EQ(seen.size(), 1U);
}

TEST(EmcyEndToEnd, ConsumerSeesTheProducersErrorAndItsReset) {
    ServiceBench bench;
    ObjectDictionary od;
    add_error_objects(od, kEpos2ErrorHistoryEntries);
    add_emcy_objects(od, kNode);
    EmcyProducer producer(bench.loop, *bench.device, od);
    EmcyConsumer consumer;
    std::vector<Emergency> seen;
    consumer.on_emergency([&](const Emergency& emergency) { seen.push_back(emergency); });
    bench.tester->on_receive([&](const can::Frame& frame) { consumer.on_frame(frame); });
    producer.set_nmt_state(NmtState::Operational);
    consumer.set_nmt_state(NmtState::Operational);

    producer.raise(0x8611, error_register::kDeviceProfile);
    producer.clear(0x8611);
    bench.run_for(1ms);
    EXPECT_EQ(seen, (std::vector<Emergency>{{kNode, 0x8611, 0x21, {}}, {kNode, 0x0000, 0x00, {}}}));
}

} // namespace
} // namespace eposp::canopen
