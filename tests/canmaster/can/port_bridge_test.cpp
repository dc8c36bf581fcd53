#include "eposp/can/port_bridge.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace eposp::can {
namespace {

/// A port whose receptions the test triggers and whose sends it records.
class RecordingPort final : public Port {
public:
    SendStatus send(const Frame& frame) override {
        sent.push_back(frame);
        return answer;
    }
    ErrorState error_state() const override { return ErrorState::Active; }
    std::string_view name() const override { return "recording"; }
    void receive(const Frame& frame) const { deliver(frame); }

    std::vector<Frame> sent;
    SendStatus answer = SendStatus::Queued;
};

TEST(PortBridge, ForwardsFramesBothWays) {
    RecordingPort a;
    RecordingPort b;
    const PortBridge bridge(a, b);
    const Frame from_a = Frame::data_frame(0x181, {1, 2, 3});
    const Frame from_b = Frame::data_frame(0x1234567, {4}, true);
    a.receive(from_a);
    b.receive(from_b);
    ASSERT_EQ(b.sent.size(), 1U);
    EXPECT_EQ(b.sent[0], from_a);
    ASSERT_EQ(a.sent.size(), 1U);
    EXPECT_EQ(a.sent[0], from_b);
    EXPECT_EQ(bridge.a_to_b().forwarded, 1U);
    EXPECT_EQ(bridge.b_to_a().forwarded, 1U);
}

TEST(PortBridge, CountsFramesTheOtherSideRefuses) {
    RecordingPort a;
    RecordingPort b;
    b.answer = SendStatus::TxOverflow;
    const PortBridge bridge(a, b);
    a.receive(Frame::data_frame(0x100, {}));
    a.receive(Frame::data_frame(0x101, {}));
    EXPECT_EQ(bridge.a_to_b().forwarded, 0U);
    EXPECT_EQ(bridge.a_to_b().refused, 2U);
    EXPECT_EQ(bridge.a_to_b().last_refusal, SendStatus::TxOverflow);
}

TEST(PortBridge, StopsForwardingWhenDestroyed) {
    RecordingPort a;
    RecordingPort b;
    { const PortBridge bridge(a, b); }
    a.receive(Frame::data_frame(0x100, {}));
    EXPECT_TRUE(b.sent.empty());
}

} // namespace
} // namespace eposp::can
