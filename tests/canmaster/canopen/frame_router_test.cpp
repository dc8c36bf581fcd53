// FrameRouter: a received frame reaches only the receivers of its identifier.
#include "eposp/canopen/frame_router.hpp"

#include <deque>
#include <functional>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::canopen {
namespace {

/// A service as the router sees it: what it does with a frame is the test's.
struct Receiver {
    std::function<void(const can::Frame&)> handle;
    void on_frame(const can::Frame& frame) { handle(frame); }
};

struct Routed {
    std::deque<Receiver> receivers; ///< outlive the router, and stay put
    FrameRouter router;
    std::vector<std::string> heard;

    /// A receiver named `name` that takes `keys` (which the test may change).
    void add(const std::string& name, ReceiveKeys& keys) {
        receivers.push_back({[this, name](const can::Frame& frame) {
            heard.push_back(name + ":" + std::to_string(frame.id));
        }});
        router.add([&keys](ReceiveKeys& out) { out.insert(out.end(), keys.begin(), keys.end()); },
                   receivers.back());
    }
};

/// A port whose received frames the test hands in.
class TestPort final : public can::Port {
public:
    can::SendStatus send(const can::Frame&) override { return can::SendStatus::Queued; }
    can::ErrorState error_state() const override { return can::ErrorState::Active; }
    std::string_view name() const override { return "test"; }
    void receive(const can::Frame& frame) const { deliver(frame); }
};

can::Frame extended_frame(std::uint32_t id) {
    can::Frame frame = can::Frame::data_frame(id, {0});
    frame.extended = true;
    return frame;
}

TEST(FrameRouter, AFrameReachesOnlyTheReceiversOfItsIdentifierInTheOrderAdded) {
    Routed routed;
    ReceiveKeys sync{0x080};
    ReceiveKeys sdo{0x601};
    ReceiveKeys also_sync{0x080, 0x181};
    routed.add("sync", sync);
    routed.add("sdo", sdo);
    routed.add("pdo", also_sync);

    routed.router.dispatch(can::Frame::data_frame(0x080, {}));
    routed.router.dispatch(can::Frame::data_frame(0x601, {0x40, 0, 0x10, 0, 0, 0, 0, 0}));
    routed.router.dispatch(can::Frame::data_frame(0x200, {1}));

    EXPECT_EQ(routed.heard, (std::vector<std::string>{"sync:128", "pdo:128", "sdo:1537"}));
}

TEST(FrameRouter, ElevenAndTwentyNineBitIdentifiersAreDifferentKeys) {
    Routed routed;
    ReceiveKeys standard{receive_key(0x181)};
    ReceiveKeys extended{receive_key(kCobIdExtended | 0x181)};
    routed.add("standard", standard);
    routed.add("extended", extended);

    routed.router.dispatch(extended_frame(0x181));
    routed.router.dispatch(can::Frame::data_frame(0x181, {0}));

    EXPECT_EQ(routed.heard, (std::vector<std::string>{"extended:385", "standard:385"}));
}

TEST(FrameRouter, AKeyListedTwiceDeliversTheFrameOnce) {
    Routed routed;
    ReceiveKeys twice{0x181, 0x181};
    routed.add("pdo", twice);
    routed.router.dispatch(can::Frame::data_frame(0x181, {0}));
    EXPECT_EQ(routed.heard, (std::vector<std::string>{"pdo:385"}));
}

TEST(FrameRouter, AfterInvalidateTheReceiversAreAskedAgain) {
    Routed routed;
    ReceiveKeys sync{0x080};
    routed.add("sync", sync);
    routed.router.dispatch(can::Frame::data_frame(0x080, {}));

    sync = {0x081}; // 0x1005 written: the table still routes the old identifier
    routed.router.dispatch(can::Frame::data_frame(0x081, {}));
    routed.router.invalidate();
    routed.router.dispatch(can::Frame::data_frame(0x080, {}));
    routed.router.dispatch(can::Frame::data_frame(0x081, {}));

    EXPECT_EQ(routed.heard, (std::vector<std::string>{"sync:128", "sync:129"}));
}

TEST(FrameRouter, ErrorFramesReachNoReceiver) {
    Routed routed;
    ReceiveKeys keys{0x004}; // an error frame's id holds its error class (here: controller)
    routed.add("any", keys);
    can::Frame error = can::Frame::data_frame(0x004, {0, 0x04});
    error.error = true;
    routed.router.dispatch(error);
    EXPECT_TRUE(routed.heard.empty());
}

TEST(FrameRouter, AReceiverThatInvalidatesWhileHandlingAFrameChangesTheNextFrameOnly) {
    ReceiveKeys keys{0x000};
    std::vector<std::uint32_t> heard;
    FrameRouter router;
    Receiver moving{[&](const can::Frame& frame) {
        heard.push_back(frame.id);
        keys = {0x001}; // e.g. a reset communication that moves the node's identifiers
        router.invalidate();
    }};
    Receiver staying{[&](const can::Frame& frame) {
        heard.push_back(0x100 + frame.id);
    }};
    router.add([&keys](ReceiveKeys& out) { out = keys; }, moving);
    router.add([](ReceiveKeys& out) { out.push_back(0x000); }, staying);

    router.dispatch(can::Frame::data_frame(0x000, {1, 0}));
    router.dispatch(can::Frame::data_frame(0x000, {1, 0}));
    router.dispatch(can::Frame::data_frame(0x001, {}));

    EXPECT_EQ(heard, (std::vector<std::uint32_t>{0x000, 0x100, 0x100, 0x001}));
}

// The port's filter follows the table: every frame while the table waits to be made (the frame
// that makes it included), then only the table's identifiers, every frame again after
// invalidate() until the next dispatch made the table anew.
TEST(FrameRouter, AFilteredPortHandsOverTheFramesOfTheTableAndEveryFrameWhileItIsStale) {
    FrameRouter router;
    TestPort port;
    std::vector<std::uint32_t> handed;
    port.on_receive([&](const can::Frame& frame) {
        handed.push_back(frame.id);
        router.dispatch(frame);
    });
    ReceiveKeys keys{0x080, kCobIdExtended | 0x181};
    std::vector<std::uint32_t> heard;
    Receiver receiver{[&heard](const can::Frame& frame) {
        heard.push_back(frame.id);
    }};
    router.add([&keys](ReceiveKeys& out) { out = keys; }, receiver);
    router.filter(port);

    port.receive(can::Frame::data_frame(0x200, {})); // stale: handed over, makes the table
    port.receive(can::Frame::data_frame(0x200, {}));
    port.receive(can::Frame::data_frame(0x080, {}));
    port.receive(extended_frame(0x300)); // 29-bit frames are all handed over
    keys = {0x200};
    router.invalidate();
    port.receive(can::Frame::data_frame(0x080, {})); // stale again: handed over, not heard
    port.receive(can::Frame::data_frame(0x080, {}));
    port.receive(can::Frame::data_frame(0x200, {}));

    EXPECT_EQ(handed, (std::vector<std::uint32_t>{0x200, 0x080, 0x300, 0x080, 0x200}));
    EXPECT_EQ(heard, (std::vector<std::uint32_t>{0x080, 0x200}));
}

} // namespace
} // namespace eposp::canopen
