#include "eposp/can/virtual_bus.hpp"
#include "virtual_bus_test_support.hpp"

#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

// The bus hands a frame only to the controllers it concerns (their filter accepts it, or their
// receive error counter or receive queue needs it); every other controller must behave as if
// it had received the frame too: these tests hold the bus to what each controller would see.
namespace eposp::can {
namespace {

using testing::Inbox;
using testing::WireLog;

Port::StandardIds only(std::initializer_list<std::uint32_t> ids) {
    Port::StandardIds accepted;
    for (const std::uint32_t id : ids) {
        accepted.set(id);
    }
    return accepted;
}

class VirtualBusReceiversTest : public ::testing::Test {
protected:
    core::EventLoop loop;
    VirtualBus bus{loop};
    WireLog wire{bus};
};

// 70 controllers (two words of the index), each filtering for its own identifier, and one that
// takes everything: each frame reaches the observers, the controller of its identifier and the
// one without filter; every controller but the sender counts every frame.
TEST_F(VirtualBusReceiversTest, AFrameReachesTheObserversItsFilteringPortAndThoseWithoutFilter) {
    constexpr std::size_t kPorts = 70;
    auto master = bus.connect("master", kPorts);
    Inbox at_master(*master, loop);
    std::vector<std::unique_ptr<VirtualPort>> ports;
    std::vector<std::unique_ptr<Inbox>> inboxes;
    for (std::size_t n = 0; n < kPorts; ++n) {
        ports.push_back(bus.connect("node" + std::to_string(n)));
        inboxes.push_back(std::make_unique<Inbox>(*ports.back(), loop));
        ports.back()->accept_only(only({0x100U + static_cast<std::uint32_t>(n)}));
    }
    for (std::size_t n = 0; n < kPorts; ++n) {
        ASSERT_EQ(master->send(Frame::data_frame(0x100U + static_cast<std::uint32_t>(n),
                                                 {static_cast<std::uint8_t>(n)})),
                  SendStatus::Queued);
    }
    ASSERT_EQ(ports[3]->send(Frame::data_frame(0x7FF, {})), SendStatus::Queued);
    loop.run();

    ASSERT_EQ(wire.events.size(), kPorts + 1);
    EXPECT_EQ(at_master.frames.size(), 1U) << "its own frames do not come back";
    for (std::size_t n = 0; n < kPorts; ++n) {
        ASSERT_EQ(inboxes[n]->frames.size(), 1U) << n;
        EXPECT_EQ(inboxes[n]->frames[0].id, 0x100U + n);
        EXPECT_EQ(ports[n]->statistics().rx_frames, n == 3 ? kPorts : kPorts + 1) << n;
    }
    EXPECT_EQ(master->statistics().rx_frames, 1U);
}

// ISO 11898-1:2015, 12.1.4.2: every successful reception counts the receive error counter
// down, also of a controller whose acceptance filter then hides the frame.
TEST_F(VirtualBusReceiversTest, AFilteredFrameStillCountsTheReceiveErrorCounterDown) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    auto c = bus.connect("c");
    Inbox at_b(*b, loop);
    b->accept_only(only({0x123}));
    bus.corrupt_frames({}, 3);
    a->send(Frame::data_frame(0x100, {}));
    loop.run();
    EXPECT_EQ(b->statistics().receive_error_counter, 2U) << "3 errors, then 1 success";
    EXPECT_EQ(c->statistics().receive_error_counter, 2U);
    a->send(Frame::data_frame(0x100, {}));
    a->send(Frame::data_frame(0x100, {}));
    a->send(Frame::data_frame(0x100, {}));
    loop.run();
    EXPECT_EQ(b->statistics().receive_error_counter, 0U);
    EXPECT_EQ(c->statistics().receive_error_counter, 0U);
    EXPECT_TRUE(at_b.frames.empty());
    EXPECT_EQ(b->statistics().rx_frames, 4U);
}

// A frame lost while a filtering port's queue is full counts as an overflow, not a reception.
TEST_F(VirtualBusReceiversTest, APausedFilteringPortQueuesAndLosesFramesItWouldHide) {
    BusConfig config;
    config.rx_queue_capacity = 2;
    VirtualBus small(loop, config);
    auto a = small.connect("a");
    auto b = small.connect("b");
    Inbox at_b(*b, loop);
    b->accept_only(only({0x001}));
    b->pause_receive(true);
    for (std::uint32_t id : {0x001U, 0x002U, 0x003U}) {
        a->send(Frame::data_frame(id, {}));
    }
    loop.run();
    EXPECT_EQ(b->statistics().rx_frames, 2U);
    EXPECT_EQ(b->statistics().rx_overflows, 1U);
    b->pause_receive(false);
    ASSERT_EQ(at_b.frames.size(), 1U);
    a->send(Frame::data_frame(0x002, {}));
    loop.run();
    EXPECT_EQ(b->statistics().rx_frames, 3U);
    EXPECT_EQ(at_b.frames.size(), 1U);
}

// A receive handler may change the filter of a controller whose turn comes later in the same
// frame: that controller gets the frame under its new filter, as before the index.
TEST_F(VirtualBusReceiversTest, AFilterChangedBeforeAPortsTurnDecidesForThatFrame) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    auto c = bus.connect("c");
    Inbox at_c(*c, loop);
    c->accept_only(only({0x001}));
    b->on_receive([&c](const Frame&) { c->accept_all(); });
    a->send(Frame::data_frame(0x200, {}));
    loop.run();
    ASSERT_EQ(at_c.frames.size(), 1U);
    EXPECT_EQ(at_c.frames[0].id, 0x200U);
}

// A bus-off controller receives nothing; before and after, it counts the frames its filter
// hides. A controller connected while a frame is on the wire does not count that frame.
TEST_F(VirtualBusReceiversTest, FramesCountOnlyWhileAPortTakesPartAndOnceItHasConnected) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    auto observer = bus.connect("c");
    b->accept_only(only({}));
    a->send(Frame::data_frame(0x100, {}));
    loop.run();
    EXPECT_EQ(b->statistics().rx_frames, 1U);
    b->force_error_state(ErrorState::BusOff);
    a->send(Frame::data_frame(0x100, {}));
    loop.run_for(std::chrono::microseconds(100));
    EXPECT_EQ(b->statistics().rx_frames, 1U) << "bus-off";
    loop.run(); // recovers after 128 x 11 recessive bits
    ASSERT_EQ(b->error_state(), ErrorState::Active);
    std::unique_ptr<VirtualPort> late;
    a->send(Frame::data_frame(0x100, {}));
    loop.at(loop.now() + std::chrono::microseconds(10), [&] {
        late = bus.connect("late");
        late->accept_only(only({}));
    });
    loop.run();
    EXPECT_EQ(b->statistics().rx_frames, 2U);
    EXPECT_EQ(late->statistics().rx_frames, 0U);
    EXPECT_EQ(observer->statistics().rx_frames, 3U);
    a->send(Frame::data_frame(0x100, {}));
    loop.run();
    EXPECT_EQ(late->statistics().rx_frames, 1U);
}

// A receive handler reads the statistics of controllers that had their turn and of those still
// waiting for it: a frame counts for a controller from its turn on.
TEST_F(VirtualBusReceiversTest, AFrameCountsForEachPortFromItsTurnOn) {
    auto a = bus.connect("a");
    auto b = bus.connect("b");
    auto c = bus.connect("c");
    auto d = bus.connect("d");
    b->accept_only(only({}));
    d->accept_only(only({}));
    std::vector<std::uint64_t> seen;
    c->on_receive([&](const Frame&) {
        seen = {a->statistics().rx_frames, b->statistics().rx_frames, c->statistics().rx_frames,
                d->statistics().rx_frames};
    });
    a->send(Frame::data_frame(0x100, {}));
    loop.run();
    EXPECT_EQ(seen, (std::vector<std::uint64_t>{0, 1, 1, 0}));
    EXPECT_EQ(d->statistics().rx_frames, 1U);
}

} // namespace
} // namespace eposp::can
