#include "eposp/can/error_frame.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "virtual_bus_test_support.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <utility>

namespace eposp::can {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;
using testing::at_us;
using testing::Inbox;
using testing::RecordedEvent;
using testing::WireLog;

// At 1 Mbit/s one bit is 1 us. Identifier 0, DLC 0: SOF..CRC are 40 bits with the stuff
// bits, its last bit dominant; EOF ends at 50 us, the intermission at 53 us.
const Frame kZeroFrame = Frame::data_frame(0x000, {});
constexpr std::int64_t kZeroFrameStuffedBits = 40;
// Error flag 6 + error delimiter 8, then the intermission 3.
constexpr std::int64_t kErrorFrameBits = 14;
constexpr std::int64_t kIntermissionBits = 3;
constexpr std::int64_t kSuspendBits = 8;
// 128 occurrences of 11 recessive bits.
constexpr std::int64_t kRecoveryBits = 128 * 11;

/// Error states a port reported, with the times.
struct StateLog {
    StateLog(Port& port, const core::EventLoop& loop) {
        port.on_error_state(
            [this, &loop](ErrorState state) { changes.emplace_back(loop.now(), state); });
    }
    std::vector<ErrorState> states() const {
        std::vector<ErrorState> out;
        for (const auto& change : changes) {
            out.push_back(change.second);
        }
        return out;
    }
    std::vector<std::pair<core::TimePoint, ErrorState>> changes;
};

std::vector<RecordedEvent> error_frames(const WireLog& wire) {
    std::vector<RecordedEvent> out;
    for (const RecordedEvent& event : wire.events) {
        if (event.frame.error) {
            out.push_back(event);
        }
    }
    return out;
}

VirtualBus::FrameFilter with_id(std::uint32_t id) {
    return [id](const Frame& frame) {
        return frame.id == id;
    };
}

class VirtualBusFaultsTest : public ::testing::Test {
protected:
    core::EventLoop loop;
    VirtualBus bus{loop};
    WireLog wire{bus};
    std::unique_ptr<VirtualPort> a = bus.connect("a");
    std::unique_ptr<VirtualPort> b = bus.connect("b");
    Inbox at_b{*b, loop};
};

// The bus keeps the name of a sender that leaves during its frame for that frame alone: the
// error frame is named after it, the next frame after its own sender.
TEST_F(VirtualBusFaultsTest, AnErrorFrameNamesTheSenderThatLeftDuringItsFrame) {
    auto c = bus.connect("c");
    bus.corrupt_frames(with_id(0x000), 1);
    a->send(Frame::data_frame(0x000, {}));
    c->send(Frame::data_frame(0x100, {}));
    loop.at(at_us(10), [&] { a.reset(); });
    loop.run();
    ASSERT_EQ(wire.events.size(), 2U);
    EXPECT_TRUE(wire.events[0].frame.error);
    EXPECT_EQ(wire.events[0].sender, "a");
    EXPECT_EQ(wire.events[1].frame.id, 0x100U);
    EXPECT_EQ(wire.events[1].sender, "c");
}

TEST_F(VirtualBusFaultsTest, DroppedFramesAreLostForReceiversAndCounted) {
    bus.drop_frames(with_id(0x181), 2);
    for (int i = 0; i < 3; ++i) {
        a->send(Frame::data_frame(0x181, {static_cast<std::uint8_t>(i)}));
    }
    a->send(Frame::data_frame(0x182, {}));
    loop.run();
    ASSERT_EQ(at_b.frames.size(), 2U);
    EXPECT_EQ(at_b.frames[0], Frame::data_frame(0x181, {2}));
    EXPECT_EQ(at_b.frames[1].id, 0x182U);
    EXPECT_EQ(wire.events.size(), 2U);
    EXPECT_EQ(bus.statistics().dropped_frames, 2U);
    EXPECT_EQ(bus.statistics().frames, 2U);
    EXPECT_EQ(a->statistics().tx_frames, 4U);
}

TEST_F(VirtualBusFaultsTest, DroppedFrameStillOccupiesTheWire) {
    bus.drop_frames();
    a->send(kZeroFrame);
    a->send(kZeroFrame);
    loop.run();
    ASSERT_EQ(wire.events.size(), 1U);
    EXPECT_EQ(wire.events[0].start, at_us(53));
    EXPECT_EQ(bus.statistics().bits, 106U);
}

TEST_F(VirtualBusFaultsTest, ShortenedFramesReachReceiversAndTheWireOneByteShort) {
    bus.shorten_frames(with_id(0x181), 2);
    a->send(Frame::data_frame(0x181, {1, 2, 3}));
    a->send(Frame::data_frame(0x181, {})); // nothing to take away: counts all the same
    a->send(Frame::data_frame(0x181, {4, 5, 6}));
    loop.run();
    ASSERT_EQ(at_b.frames.size(), 3U);
    EXPECT_EQ(at_b.frames[0], Frame::data_frame(0x181, {1, 2}));
    EXPECT_EQ(at_b.frames[1], Frame::data_frame(0x181, {}));
    EXPECT_EQ(at_b.frames[2], Frame::data_frame(0x181, {4, 5, 6}));
    ASSERT_EQ(wire.events.size(), 3U);
    EXPECT_EQ(wire.events[0].frame, Frame::data_frame(0x181, {1, 2}));
    EXPECT_EQ(bus.statistics().error_frames, 0U);
}

TEST_F(VirtualBusFaultsTest, CancelledFaultTakesNoMoreFrames) {
    const auto fault = bus.drop_frames({}, 100);
    a->send(kZeroFrame);
    loop.run();
    EXPECT_TRUE(bus.cancel_fault(fault));
    EXPECT_FALSE(bus.cancel_fault(fault));
    a->send(kZeroFrame);
    loop.run();
    EXPECT_EQ(at_b.frames.size(), 1U);
}

TEST_F(VirtualBusFaultsTest, CorruptedFrameSignalsAnErrorFrameAndIsSentAgain) {
    bus.corrupt_frames(with_id(0x000));
    a->send(kZeroFrame);
    loop.run();

    ASSERT_EQ(wire.events.size(), 2U);
    const RecordedEvent& error = wire.events[0];
    EXPECT_TRUE(error.frame.error);
    EXPECT_EQ(error.sender, "a");
    EXPECT_EQ(error.start, at_us(kZeroFrameStuffedBits));
    EXPECT_EQ(error.end, at_us(kZeroFrameStuffedBits + kErrorFrameBits));
    // Bus error on transmission, a dominant bit read back recessive, in the CRC sequence.
    EXPECT_EQ(error.frame.id, err::kProtocol | err::kBusError | err::kCounters);
    EXPECT_EQ(error.frame.dlc, 8);
    EXPECT_EQ(error.frame.data[err::kProtocolTypeByte], err::kBit0 | err::kOnTransmission);
    EXPECT_EQ(error.frame.data[err::kLocationByte],
              static_cast<std::uint8_t>(err::ErrorLocation::CrcSequence));
    EXPECT_EQ(error.frame.data[err::kTransmitCounterByte], 8);
    EXPECT_EQ(error.frame.data[err::kReceiveCounterByte], 0);

    const RecordedEvent& retransmission = wire.events[1];
    EXPECT_EQ(retransmission.frame, kZeroFrame);
    EXPECT_EQ(retransmission.start,
              at_us(kZeroFrameStuffedBits + kErrorFrameBits + kIntermissionBits));
    ASSERT_EQ(at_b.frames.size(), 1U);

    const BusStatistics stats = bus.statistics();
    EXPECT_EQ(stats.error_frames, 1U);
    EXPECT_EQ(stats.frames, 1U);
    EXPECT_EQ(stats.bits, 40U + 17U + 53U);
}

TEST_F(VirtualBusFaultsTest, ErrorCountsTransmitterEightReceiversOneSuccessMinusOne) {
    bus.corrupt_frames({}, 3);
    a->send(kZeroFrame);
    loop.run();
    // Three errors, then one success each way.
    EXPECT_EQ(a->statistics().transmit_error_counter, 3U * 8U - 1U);
    EXPECT_EQ(b->statistics().receive_error_counter, 3U - 1U);
    EXPECT_EQ(a->statistics().tx_frames, 1U);
}

// Twelve errors reach the warning level (TEC 96), sixteen error-passive (128); the success
// after them counts down to 127, the warning level again: error-active.
TEST_F(VirtualBusFaultsTest, SixteenErrorsMakeTheTransmitterPassiveAndASuccessActiveAgain) {
    StateLog states(*a, loop);
    bus.corrupt_frames({}, 16);
    a->send(kZeroFrame);
    loop.run();
    EXPECT_EQ(states.states(),
              (std::vector{ErrorState::Warning, ErrorState::Passive, ErrorState::Warning}));
    const auto errors = error_frames(wire);
    ASSERT_EQ(errors.size(), 16U);
    EXPECT_EQ(errors[11].frame.id & err::kController, err::kController);
    EXPECT_EQ(errors[11].frame.data[err::kControllerByte], err::kTxWarning);
    EXPECT_EQ(errors.back().frame.id & err::kController, err::kController);
    EXPECT_EQ(errors.back().frame.data[err::kControllerByte], err::kTxPassive);
    EXPECT_EQ(errors.back().frame.data[err::kTransmitCounterByte], 128);
    EXPECT_EQ(errors[14].frame.id & err::kController, 0U);
    EXPECT_EQ(a->statistics().transmit_error_counter, 127U);
}

TEST_F(VirtualBusFaultsTest, ErrorPassiveTransmitterSuspendsTransmissionForEightBits) {
    // TEC 128 + 8: still error-passive after each of the two successes.
    a->force_error_state(ErrorState::Passive);
    bus.corrupt_frames();
    a->send(kZeroFrame);
    a->send(kZeroFrame);
    loop.run();
    ASSERT_EQ(wire.events.size(), 3U);
    const std::int64_t retry = kZeroFrameStuffedBits + kErrorFrameBits + kIntermissionBits;
    EXPECT_EQ(wire.events[1].start, at_us(retry + kSuspendBits));
    EXPECT_EQ(wire.events[2].start, at_us(retry + kSuspendBits + 53 + kSuspendBits));
    EXPECT_EQ(a->error_state(), ErrorState::Passive);
}

TEST_F(VirtualBusFaultsTest, OtherNodeMayStartWhileThePassiveOneIsSuspended) {
    a->force_error_state(ErrorState::Passive);
    bus.corrupt_frames();
    a->send(kZeroFrame);
    b->send(Frame::data_frame(0x700, {}));
    loop.run();
    ASSERT_EQ(wire.events.size(), 3U);
    EXPECT_TRUE(wire.events[0].frame.error);
    EXPECT_EQ(wire.events[1].frame.id, 0x700U);
    EXPECT_EQ(wire.events[2].frame, kZeroFrame);
}

TEST_F(VirtualBusFaultsTest, ThirtyTwoErrorsMakeTheTransmitterBusOff) {
    StateLog states(*a, loop);
    bus.corrupt_frames({}, 32);
    a->send(kZeroFrame);
    loop.run_for(milliseconds(2));
    ASSERT_GE(states.changes.size(), 3U);
    EXPECT_EQ(states.changes[0].second, ErrorState::Warning);
    EXPECT_EQ(states.changes[1].second, ErrorState::Passive);
    EXPECT_EQ(states.changes[2].second, ErrorState::BusOff);
    const auto errors = error_frames(wire);
    ASSERT_EQ(errors.size(), 32U);
    EXPECT_EQ(errors.back().frame.id & err::kBusOff, err::kBusOff);
    EXPECT_EQ(b->statistics().receive_error_counter, 32U);
    EXPECT_TRUE(at_b.frames.empty());

    // Attempts start 57 bits apart while active and 65 while passive (suspend transmission);
    // the 32nd error frame ends 54 bits after its attempt started.
    const core::TimePoint bus_off = states.changes[2].first;
    EXPECT_EQ(bus_off, at_us(15 * 57 + 16 * 65 + 54));
    EXPECT_EQ(a->send(kZeroFrame), SendStatus::BusOff);
}

TEST_F(VirtualBusFaultsTest, BusOffControllerRecoversAfter128RunsOfElevenRecessiveBits) {
    StateLog states(*a, loop);
    a->send(kZeroFrame); // queued before bus-off: sent after the recovery
    a->force_error_state(ErrorState::BusOff);
    EXPECT_EQ(a->statistics().transmit_error_counter, 256U);
    loop.run();
    ASSERT_EQ(states.changes.size(), 2U);
    EXPECT_EQ(states.changes[0], std::pair(at_us(0), ErrorState::BusOff));
    EXPECT_EQ(states.changes[1], std::pair(at_us(kRecoveryBits), ErrorState::Active));
    EXPECT_EQ(a->statistics().transmit_error_counter, 0U);
    ASSERT_EQ(wire.events.size(), 1U);
    EXPECT_EQ(wire.events[0].start, at_us(kRecoveryBits));
}

TEST_F(VirtualBusFaultsTest, BusOffRecoveryCountsOneRunPerFrameUnderFullLoad) {
    // c and d keep the bus busy; each frame ends with ACK delimiter, EOF and intermission: 11
    // recessive bits before the next start of frame, exactly one run.
    auto c = bus.connect("c");
    auto d = bus.connect("d");
    c->on_receive([&](const Frame& frame) { c->send(frame); });
    d->on_receive([&](const Frame& frame) { d->send(frame); });
    StateLog states(*a, loop);
    a->force_error_state(ErrorState::BusOff);
    c->send(kZeroFrame);
    loop.run_for(milliseconds(10));
    ASSERT_EQ(states.changes.size(), 2U);
    EXPECT_EQ(states.changes[1], std::pair(at_us(128 * 53), ErrorState::Active));
}

// The recovering controllers count their runs at each start of frame: one leaving in the middle
// of its recovery stops nobody else's count, and a controller bus-off a second time counts anew.
TEST_F(VirtualBusFaultsTest, RecoveryCountsOnWhenAnotherRecoveringControllerLeaves) {
    auto c = bus.connect("c");
    auto d = bus.connect("d");
    c->on_receive([&](const Frame& frame) { c->send(frame); });
    d->on_receive([&](const Frame& frame) { d->send(frame); });
    auto leaving = bus.connect("leaving");
    StateLog states(*a, loop);
    leaving->force_error_state(ErrorState::BusOff);
    a->force_error_state(ErrorState::BusOff);
    c->send(kZeroFrame);
    loop.run_for(microseconds(64 * 53));
    leaving.reset();
    loop.run_for(milliseconds(10) - microseconds(64 * 53));
    ASSERT_EQ(states.changes.size(), 2U);
    EXPECT_EQ(states.changes[1], std::pair(at_us(128 * 53), ErrorState::Active));

    // Bus-off again at 10 ms, 36 bits into a frame: the first run counted ends at the next
    // start of frame, 10017 us, the 128th 127 frames later.
    a->force_error_state(ErrorState::BusOff);
    loop.run_for(milliseconds(10));
    ASSERT_EQ(states.changes.size(), 4U);
    EXPECT_EQ(states.changes[2], std::pair(at_us(10'000), ErrorState::BusOff));
    EXPECT_EQ(states.changes[3], std::pair(at_us(10'017 + 127 * 53), ErrorState::Active));
}

TEST(VirtualBusFaults, BusOffRecoveryOnRequestWaitsForRecover) {
    core::EventLoop loop;
    VirtualBus bus(loop, BusConfig{.bus_off_recovery = BusOffRecovery::OnRequest});
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    StateLog states(*a, loop);
    a->force_error_state(ErrorState::BusOff);
    loop.run_for(milliseconds(10));
    EXPECT_EQ(a->error_state(), ErrorState::BusOff);
    a->recover();
    loop.run();
    ASSERT_EQ(states.changes.size(), 2U);
    EXPECT_EQ(states.changes[1], std::pair(at_us(10'000 + kRecoveryBits), ErrorState::Active));
}

TEST(VirtualBusFaults, LoneNodeEndsErrorPassiveNotBusOff) {
    core::EventLoop loop;
    VirtualBus bus(loop);
    WireLog wire(bus);
    auto a = bus.connect("a");
    StateLog states(*a, loop);
    a->send(kZeroFrame);
    loop.run_for(milliseconds(100));
    EXPECT_EQ(states.states(), (std::vector{ErrorState::Warning, ErrorState::Passive}));
    EXPECT_EQ(a->statistics().transmit_error_counter, 128U);
    EXPECT_EQ(a->statistics().tx_frames, 0U);

    // ACK error: the flag starts after the ACK slot, at bit 42.
    ASSERT_GT(wire.events.size(), 16U);
    const RecordedEvent& first = wire.events[0];
    EXPECT_EQ(first.start, at_us(kZeroFrameStuffedBits + 2));
    EXPECT_EQ(first.end, at_us(kZeroFrameStuffedBits + 2 + kErrorFrameBits));
    EXPECT_EQ(first.frame.id, err::kProtocol | err::kBusError | err::kCounters | err::kNoAck);
    EXPECT_EQ(first.frame.data[err::kLocationByte],
              static_cast<std::uint8_t>(err::ErrorLocation::AckSlot));
    // Active attempts take 59 bits; passive ones 8 more.
    EXPECT_EQ(wire.events[1].start - wire.events[0].start, microseconds(59));
    EXPECT_EQ(wire.events[17].start - wire.events[16].start, microseconds(67));
}

TEST_F(VirtualBusFaultsTest, FrameNobodyCanAcknowledgeIsAnAckError) {
    b->force_error_state(ErrorState::BusOff);
    a->send(kZeroFrame);
    loop.run_for(microseconds(500));
    EXPECT_TRUE(at_b.frames.empty());
    ASSERT_FALSE(wire.events.empty());
    EXPECT_EQ(wire.events[0].frame.id & err::kNoAck, err::kNoAck);
}

TEST_F(VirtualBusFaultsTest, ForcedStatesAreReportedAndCounted) {
    StateLog states(*a, loop);
    a->force_error_state(ErrorState::Passive);
    EXPECT_EQ(a->error_state(), ErrorState::Passive);
    EXPECT_EQ(a->statistics().transmit_error_counter, 128U);
    a->force_error_state(ErrorState::Active);
    EXPECT_EQ(states.states(), (std::vector{ErrorState::Passive, ErrorState::Active}));
}

TEST_F(VirtualBusFaultsTest, BabblingNodeStarvesLowerPriorityTraffic) {
    auto c = bus.connect("c");
    a->babble(Frame::data_frame(0x050, {0xBA}));
    b->send(Frame::data_frame(0x100, {}));
    loop.at(at_us(1000), [&] { c->send(Frame::data_frame(0x010, {})); });
    loop.run_for(milliseconds(5));
    std::size_t babbled = 0;
    for (const RecordedEvent& event : wire.events) {
        EXPECT_NE(event.frame.id, 0x100U);
        babbled += event.frame.id == 0x050 ? 1 : 0;
    }
    EXPECT_GT(babbled, 50U);
    EXPECT_EQ(std::ranges::count(wire.ids(), 0x010U), 1);

    a->stop_babbling();
    wire.events.clear();
    loop.run();
    // The babbled frame on the wire at the time completes, then the starved one goes.
    EXPECT_LE(std::ranges::count(wire.ids(), 0x050U), 1);
    EXPECT_EQ(wire.ids().back(), 0x100U);
}

} // namespace
} // namespace eposp::can
