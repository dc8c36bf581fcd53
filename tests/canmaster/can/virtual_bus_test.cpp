#include "eposp/can/frame_timing.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "virtual_bus_test_support.hpp"

#include <gtest/gtest.h>
#include <ostream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace eposp::can {
namespace {

using std::chrono::microseconds;
using testing::at_us;
using testing::Inbox;
using testing::WireLog;

// At 1 Mbit/s one bit is 1 us. Identifier 0, DLC 0 is 53 bits: its EOF ends at 50 us, its
// intermission at 53 us.
const Frame kZeroFrame = Frame::data_frame(0x000, {});

class VirtualBusTest : public ::testing::Test {
protected:
    core::EventLoop loop;
    VirtualBus bus{loop};
    WireLog wire{bus};
};

TEST_F(VirtualBusTest, ReceiverGetsTheFrameAtItsEndOfFrame) {
    auto sender = bus.connect("a");
    auto receiver = bus.connect("b");
    Inbox inbox(*receiver, loop);
    ASSERT_EQ(sender->send(kZeroFrame), SendStatus::Queued);
    loop.run();
    ASSERT_EQ(inbox.frames.size(), 1U);
    EXPECT_EQ(inbox.frames[0], kZeroFrame);
    EXPECT_EQ(inbox.times[0], at_us(50));
    ASSERT_EQ(wire.events.size(), 1U);
    EXPECT_EQ(wire.events[0].start, at_us(0));
    EXPECT_EQ(wire.events[0].end, at_us(50));
    EXPECT_EQ(wire.events[0].sender, "a");
}

TEST_F(VirtualBusTest, ControllerDoesNotReceiveItsOwnFrame) {
    auto sender = bus.connect("a");
    auto receiver = bus.connect("b");
    Inbox own(*sender, loop);
    Inbox other(*receiver, loop);
    sender->send(kZeroFrame);
    loop.run();
    EXPECT_TRUE(own.frames.empty());
    EXPECT_EQ(other.frames.size(), 1U);
}

// A port's acceptance filter hides frames from its handler only: the controller still counts
// them, queues them while paused, and a new handler takes every frame again.
TEST_F(VirtualBusTest, AnAcceptanceFilterHidesFramesFromTheHandlerOnly) {
    auto sender = bus.connect("a");
    auto receiver = bus.connect("b");
    std::vector<Frame> heard;
    receiver->on_receive([&heard](const Frame& frame) { heard.push_back(frame); });
    Port::StandardIds ids;
    ids.set(0x181);
    receiver->accept_only(ids);
    Frame extended = Frame::data_frame(0x182, {3});
    extended.extended = true;
    const std::vector<Frame> sent{Frame::data_frame(0x181, {1}), Frame::data_frame(0x182, {2}),
                                  extended};
    for (const Frame& frame : sent) {
        ASSERT_EQ(sender->send(frame), SendStatus::Queued);
    }
    loop.run();
    EXPECT_EQ(heard, (std::vector<Frame>{sent[0], sent[2]}));
    EXPECT_EQ(receiver->statistics().rx_frames, 3U);
    EXPECT_EQ(sender->statistics().tx_frames, 3U);

    heard.clear();
    receiver->pause_receive(true);
    for (const Frame& frame : sent) {
        ASSERT_EQ(sender->send(frame), SendStatus::Queued);
    }
    loop.run();
    EXPECT_EQ(receiver->statistics().rx_frames, 6U) << "queued while paused, filtered or not";
    receiver->pause_receive(false);
    EXPECT_EQ(heard, (std::vector<Frame>{sent[0], sent[2]}));

    heard.clear();
    receiver->on_receive([&heard](const Frame& frame) { heard.push_back(frame); });
    ASSERT_EQ(sender->send(sent[1]), SendStatus::Queued);
    loop.run();
    EXPECT_EQ(heard, (std::vector<Frame>{sent[1]}));
}

TEST_F(VirtualBusTest, EveryOtherPortReceivesInBusOrder) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    auto c = bus.connect("c");
    Inbox at_b(*b, loop);
    Inbox at_c(*c, loop);
    a->send(Frame::data_frame(0x200, {1}));
    b->send(Frame::data_frame(0x100, {2}));
    loop.run();
    ASSERT_EQ(at_c.frames.size(), 2U);
    EXPECT_EQ(at_c.frames[0].id, 0x100U);
    EXPECT_EQ(at_c.frames[1].id, 0x200U);
    ASSERT_EQ(at_b.frames.size(), 1U);
    EXPECT_EQ(at_b.frames[0].id, 0x200U);
}

TEST_F(VirtualBusTest, LowerIdentifierWinsArbitration) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    auto c = bus.connect("c");
    a->send(Frame::data_frame(0x300, {}));
    b->send(Frame::data_frame(0x100, {}));
    c->send(Frame::data_frame(0x200, {}));
    loop.run();
    EXPECT_EQ(wire.ids(), (std::vector<std::uint32_t>{0x100, 0x200, 0x300}));
}

struct ArbitrationCase {
    const char* name;
    Frame winner;
    Frame loser;
    friend void PrintTo(const ArbitrationCase& c, std::ostream* os) { *os << c.name; }
};

class ArbitrationTest : public VirtualBusTest,
                        public ::testing::WithParamInterface<ArbitrationCase> {};

TEST_P(ArbitrationTest, WinnerIsSentFirstWhicheverPortQueuedFirst) {
    const ArbitrationCase& test = GetParam();
    for (const bool winner_first : {true, false}) {
        auto a = bus.connect("a");
        auto b = bus.connect("b");
        a->send(winner_first ? test.winner : test.loser);
        b->send(winner_first ? test.loser : test.winner);
        wire.events.clear();
        loop.run();
        ASSERT_EQ(wire.events.size(), 2U);
        EXPECT_EQ(wire.events[0].frame, test.winner);
        EXPECT_EQ(wire.events[1].frame, test.loser);
    }
}

// ISO 11898-1:2015, 10.4.2.3: the arbitration field bit by bit, dominant wins.
INSTANTIATE_TEST_SUITE_P(
    VirtualBus, ArbitrationTest,
    ::testing::Values(
        ArbitrationCase{"LowerStandardId", Frame::data_frame(0x100, {}),
                        Frame::data_frame(0x101, {})},
        ArbitrationCase{"DataBeatsRemote", Frame::data_frame(0x100, {}),
                        Frame::remote_frame(0x100, 0)},
        ArbitrationCase{"StandardDataBeatsExtendedViaRtrAndSrr", Frame::data_frame(0x100, {}),
                        Frame::data_frame(0x100 << 18, {}, true)},
        ArbitrationCase{"StandardRemoteBeatsExtendedViaIde", Frame::remote_frame(0x100, 0),
                        Frame::data_frame(0x100 << 18, {}, true)},
        ArbitrationCase{"LowerBaseIdBeatsStandard", Frame::data_frame(0x0FF << 18, {}, true),
                        Frame::data_frame(0x100, {})},
        ArbitrationCase{"ExtendedDataBeatsExtendedRemote", Frame::data_frame(0x1234567, {}, true),
                        Frame::remote_frame(0x1234567, 0, true)},
        ArbitrationCase{"LowerIdExtension", Frame::data_frame(0x1234566, {}, true),
                        Frame::data_frame(0x1234567, {}, true)}),
    [](const ::testing::TestParamInfo<ArbitrationCase>& test) { return test.param.name; });

TEST_F(VirtualBusTest, FramesQueuedAtTheSameInstantAllCompete) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    // Two timers of the same instant: the first send must not seize the bus before the second.
    loop.at(at_us(100), [&] { a->send(Frame::data_frame(0x300, {})); });
    loop.at(at_us(100), [&] { b->send(Frame::data_frame(0x100, {})); });
    loop.run();
    EXPECT_EQ(wire.ids(), (std::vector<std::uint32_t>{0x100, 0x300}));
    EXPECT_EQ(wire.events[0].start, at_us(100));
}

// The arbitration where a frame's intermission ends takes the frames queued at that instant by
// the events that run before it, those scheduled while the frame was on the wire included.
TEST_F(VirtualBusTest, FramesQueuedWhereTheBusBecomesFreeAllCompete) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    auto c = bus.connect("c");
    a->send(kZeroFrame); // the bus is free again at 53 us
    loop.at(at_us(53), [&] { b->send(Frame::data_frame(0x300, {})); });
    loop.at(at_us(51), [&] { loop.at(at_us(53), [&] { c->send(Frame::data_frame(0x100, {})); }); });
    loop.run();
    EXPECT_EQ(wire.ids(), (std::vector<std::uint32_t>{0x000, 0x100, 0x300}));
    EXPECT_EQ(wire.events[1].start, at_us(53));
}

TEST_F(VirtualBusTest, FrameQueuedWhileBusyStartsAfterTheIntermission) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    a->send(kZeroFrame);
    loop.at(at_us(1), [&] { b->send(Frame::data_frame(0x001, {})); });
    loop.run();
    ASSERT_EQ(wire.events.size(), 2U);
    EXPECT_EQ(wire.events[0].frame.id, 0x000U);
    EXPECT_EQ(wire.events[1].start, at_us(53));
}

TEST_F(VirtualBusTest, EachPortSendsItsQueueInOrder) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    a->send(Frame::data_frame(0x300, {}));
    a->send(Frame::data_frame(0x100, {}));
    b->send(Frame::data_frame(0x200, {}));
    loop.run();
    // a's head 0x300 loses to 0x200; a's 0x100 waits behind its 0x300.
    EXPECT_EQ(wire.ids(), (std::vector<std::uint32_t>{0x200, 0x300, 0x100}));
}

TEST_F(VirtualBusTest, WithdrawTakesBackQueuedFramesButNotTheOneOnTheWire) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    a->send(Frame::data_frame(0x181, {}));
    a->send(Frame::data_frame(0x182, {}));
    a->send(Frame::data_frame(0x300, {}));
    a->send(Frame::data_frame(0x183, {}));
    loop.run_for(microseconds(10)); // 0x181 is on the wire
    const auto is_pdo = [](const Frame& frame) {
        return frame.id >= 0x181 && frame.id <= 0x183;
    };
    EXPECT_EQ(a->withdraw(is_pdo), 2U);
    EXPECT_EQ(b->withdraw(is_pdo), 0U);
    loop.run();
    EXPECT_EQ(wire.ids(), (std::vector<std::uint32_t>{0x181, 0x300}));
}

TEST_F(VirtualBusTest, BackToBackFramesFollowEachOtherWithoutGap) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    for (int i = 0; i < 3; ++i) {
        a->send(kZeroFrame);
    }
    loop.run();
    ASSERT_EQ(wire.events.size(), 3U);
    EXPECT_EQ(wire.events[1].start, at_us(53));
    EXPECT_EQ(wire.events[2].start, at_us(106));
    EXPECT_EQ(wire.events[2].end, at_us(156));
}

TEST(VirtualBus, FrameTimeScalesWithTheBitRate) {
    core::EventLoop loop;
    VirtualBus bus(loop, BusConfig{.bitrate = 10'000});
    EXPECT_EQ(bus.bit_time(), microseconds(100));
    WireLog wire(bus);
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    a->send(kZeroFrame);
    a->send(kZeroFrame);
    loop.run();
    ASSERT_EQ(wire.events.size(), 2U);
    EXPECT_EQ(wire.events[0].end, at_us(50 * 100));
    EXPECT_EQ(wire.events[1].start, at_us(53 * 100));
}

TEST(VirtualBus, ABusRestartedAtAnotherBitRateTimesItsFramesByIt) {
    core::EventLoop loop;
    VirtualBus bus(loop);
    bus.set_bitrate(10'000);
    EXPECT_EQ(bus.bit_time(), microseconds(100));
    EXPECT_EQ(bus.config().bitrate, 10'000U);
    WireLog wire(bus);
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    a->send(kZeroFrame);
    loop.run();
    ASSERT_EQ(wire.events.size(), 1U);
    EXPECT_EQ(wire.events[0].end, at_us(50 * 100));
    EXPECT_THROW(bus.set_bitrate(300'000), std::invalid_argument);
    EXPECT_EQ(bus.config().bitrate, 10'000U);
}

TEST(VirtualBus, RejectsBitRatesOutsideTenKbitToOneMbit) {
    core::EventLoop loop;
    EXPECT_THROW(VirtualBus(loop, BusConfig{.bitrate = 5'000}), std::invalid_argument);
    EXPECT_THROW(VirtualBus(loop, BusConfig{.bitrate = 2'000'000}), std::invalid_argument);
    EXPECT_THROW(VirtualBus(loop, BusConfig{.bitrate = 300'000}), std::invalid_argument);
    EXPECT_NO_THROW(VirtualBus(loop, BusConfig{.bitrate = 800'000}));
}

TEST_F(VirtualBusTest, InvalidFramesAreRefused) {
    auto a = bus.connect("a");
    Frame too_long = kZeroFrame;
    too_long.dlc = 9;
    EXPECT_EQ(a->send(too_long), SendStatus::InvalidFrame);
    EXPECT_EQ(a->send(Frame::data_frame(0x800, {})), SendStatus::InvalidFrame);
    Frame error;
    error.error = true;
    EXPECT_EQ(a->send(error), SendStatus::InvalidFrame);
}

TEST(VirtualBus, TransmitQueueOverflowIsRefusedCountedAndReported) {
    core::EventLoop loop;
    VirtualBus bus(loop, BusConfig{.tx_queue_capacity = 2});
    auto a = bus.connect("a");
    std::vector<Overflow> overflows;
    a->on_overflow([&](Overflow overflow, const Frame&) { overflows.push_back(overflow); });
    EXPECT_EQ(a->send(kZeroFrame), SendStatus::Queued);
    EXPECT_EQ(a->send(kZeroFrame), SendStatus::Queued);
    EXPECT_EQ(a->send(kZeroFrame), SendStatus::TxOverflow);
    EXPECT_EQ(a->statistics().tx_overflows, 1U);
    EXPECT_EQ(overflows, std::vector<Overflow>{Overflow::Transmit});
}

TEST(VirtualBus, APortConnectedWithItsOwnQueueDepthKeepsIt) {
    core::EventLoop loop;
    VirtualBus bus(loop, BusConfig{.tx_queue_capacity = 2});
    auto controller = bus.connect("controller");
    auto gateway = bus.connect("gateway", 3);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(gateway->send(kZeroFrame), SendStatus::Queued);
    }
    EXPECT_EQ(gateway->send(kZeroFrame), SendStatus::TxOverflow);
    EXPECT_EQ(controller->send(kZeroFrame), SendStatus::Queued);
    EXPECT_EQ(controller->send(kZeroFrame), SendStatus::Queued);
    EXPECT_EQ(controller->send(kZeroFrame), SendStatus::TxOverflow);
}

TEST(VirtualBus, PausedReceiverQueuesThenLosesFramesAndResumesInOrder) {
    core::EventLoop loop;
    VirtualBus bus(loop, BusConfig{.rx_queue_capacity = 2});
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    Inbox inbox(*b, loop);
    std::vector<std::uint32_t> lost;
    b->on_overflow([&](Overflow overflow, const Frame& frame) {
        EXPECT_EQ(overflow, Overflow::Receive);
        lost.push_back(frame.id);
    });
    b->pause_receive(true);
    for (std::uint32_t id = 1; id <= 3; ++id) {
        a->send(Frame::data_frame(id, {}));
    }
    loop.run();
    EXPECT_TRUE(inbox.frames.empty());
    EXPECT_EQ(b->statistics().rx_overflows, 1U);
    EXPECT_EQ(b->statistics().rx_frames, 2U);
    EXPECT_EQ(lost, std::vector<std::uint32_t>{3});

    b->pause_receive(false);
    ASSERT_EQ(inbox.frames.size(), 2U);
    EXPECT_EQ(inbox.frames[0].id, 1U);
    EXPECT_EQ(inbox.frames[1].id, 2U);
}

TEST_F(VirtualBusTest, StatisticsCountFramesBitsAndLoad) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    a->send(kZeroFrame);
    a->send(kZeroFrame);
    loop.run_for(microseconds(212)); // two frames of 53 bits in 212 us: load 0.5
    const BusStatistics stats = bus.statistics();
    EXPECT_EQ(stats.frames, 2U);
    EXPECT_EQ(stats.bits, 106U);
    EXPECT_EQ(stats.stuff_bits, 12U);
    EXPECT_EQ(stats.busy, microseconds(106));
    EXPECT_EQ(stats.elapsed, microseconds(212));
    EXPECT_DOUBLE_EQ(stats.load(), 0.5);
    EXPECT_EQ(a->statistics().tx_frames, 2U);
    EXPECT_EQ(b->statistics().rx_frames, 2U);
}

// A frame's end of frame, its end of intermission and the next start of frame run in one event
// when the loop would run them next anyway (EventLoop::advance_to). What can come between sees
// the bus as it did with an event per instant: an event due at an instant runs before the bus's
// (it was scheduled first), and a run that ends between two instants leaves the bus between them.
TEST_F(VirtualBusTest, EventsAndRunEndsBetweenAFramesInstantsSeeTheBusAsBefore) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    std::vector<std::pair<std::uint64_t, std::uint64_t>> seen; // frames and bits counted
    const auto look = [&] {
        seen.emplace_back(bus.statistics().frames, bus.statistics().bits);
    };
    a->send(kZeroFrame); // on the wire 0 .. 50 us, the bus free at 53 us
    a->send(kZeroFrame); // 53 .. 103 us, free at 106 us
    loop.at(at_us(50), look);
    b->on_receive([&](const Frame&) {
        if (seen.size() == 1) {
            loop.at(at_us(53), look); // scheduled at the end of frame, before its intermission ends
        }
    });
    // The loop counts a callback for each instant: the arbitration at 0 us, the two looks, the
    // first frame's end, its intermission's end with the second start of frame.
    EXPECT_EQ(loop.run_until(at_us(101)), 5U);
    look();
    EXPECT_EQ(loop.run_until(at_us(104)), 1U); // the second end of frame
    look();
    EXPECT_EQ(loop.run(), 1U);
    look();
    EXPECT_EQ(seen, (std::vector<std::pair<std::uint64_t, std::uint64_t>>{
                        {0, 0}, {1, 0}, {1, 53}, {2, 53}, {2, 106}}));
    ASSERT_EQ(wire.events.size(), 2U);
    EXPECT_EQ(wire.events[1].start, at_us(53));
}

TEST_F(VirtualBusTest, ContinuousTrafficLoadsTheBusFully) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    a->on_receive([&](const Frame& frame) { a->send(frame); });
    b->on_receive([&](const Frame& frame) { b->send(frame); });
    a->send(kZeroFrame);
    loop.run_for(microseconds(53 * 100));
    EXPECT_EQ(bus.statistics().frames, 100U);
    EXPECT_DOUBLE_EQ(bus.statistics().load(), 1.0);
}

TEST_F(VirtualBusTest, RemovedObserverSeesNothingMore) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    int seen = 0;
    const auto id = bus.add_observer([&](const WireEvent&) { ++seen; });
    a->send(kZeroFrame);
    loop.run();
    bus.remove_observer(id);
    a->send(kZeroFrame);
    loop.run();
    EXPECT_EQ(seen, 1);
    EXPECT_EQ(wire.events.size(), 2U);
}

TEST_F(VirtualBusTest, ObserverMayRemoveItselfWhileNotified) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    int seen = 0;
    VirtualBus::ObserverId id = 0;
    id = bus.add_observer([&](const WireEvent&) {
        ++seen;
        bus.remove_observer(id);
    });
    a->send(kZeroFrame);
    a->send(kZeroFrame);
    loop.run();
    EXPECT_EQ(seen, 1);
}

TEST_F(VirtualBusTest, PortConnectedDuringAFrameDoesNotReceiveIt) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    std::unique_ptr<VirtualPort> late;
    std::size_t late_received = 0;
    loop.at(at_us(10), [&] {
        late = bus.connect("late");
        late->on_receive([&](const Frame&) { ++late_received; });
    });
    a->send(kZeroFrame);
    loop.run();
    EXPECT_EQ(late_received, 0U);
    a->send(kZeroFrame);
    loop.run();
    EXPECT_EQ(late_received, 1U);
}

TEST_F(VirtualBusTest, ReceiverMayDisconnectAnotherPortWhileReceiving) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    auto c = bus.connect("c");
    b->on_receive([&](const Frame&) { c.reset(); });
    a->send(kZeroFrame);
    loop.run();
    EXPECT_EQ(bus.statistics().frames, 1U);
}

TEST_F(VirtualBusTest, SenderDisconnectedMidFrameStillCompletesTheFrame) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    Inbox inbox(*b, loop);
    a->send(kZeroFrame);
    loop.at(at_us(10), [&] { a.reset(); });
    loop.run();
    EXPECT_EQ(inbox.frames.size(), 1U);
    ASSERT_EQ(wire.events.size(), 1U);
    EXPECT_EQ(wire.events[0].sender, "a");
}

// The wire event names the sender as it was when the frame ended, also for the observers after
// one that disconnects the sending port.
TEST_F(VirtualBusTest, AnObserverMayDisconnectTheSenderAndTheNextStillSeesItsName) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    bus.add_observer([&](const WireEvent&) { a.reset(); });
    std::string seen;
    bus.add_observer([&](const WireEvent& event) { seen = std::string(event.sender); });
    a->send(kZeroFrame);
    loop.run();
    EXPECT_EQ(seen, "a");
    EXPECT_EQ(bus.statistics().frames, 1U);
}

TEST(VirtualBus, PortOutlivingItsBusIsDisconnected) {
    core::EventLoop loop;
    auto bus = std::make_unique<VirtualBus>(loop);
    auto a = bus->connect("a");
    bus.reset();
    EXPECT_EQ(a->send(kZeroFrame), SendStatus::Disconnected);
    EXPECT_EQ(a->name(), "a");
}

} // namespace
} // namespace eposp::can
