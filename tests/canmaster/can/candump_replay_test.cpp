#include "eposp/can/candump_replay.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <vector>

namespace eposp::can {
namespace {

using namespace std::chrono_literals;

// A port that notes when each frame was handed to it and answers with `answer`.
class RecordingPort final : public Port {
public:
    explicit RecordingPort(core::EventLoop& loop) : loop_(loop) {}

    SendStatus send(const Frame& frame) override {
        sent.push_back({loop_.now(), frame});
        return answer;
    }
    ErrorState error_state() const override { return ErrorState::Active; }
    std::string_view name() const override { return "player"; }

    struct Sent {
        core::TimePoint time;
        Frame frame;
    };
    std::vector<Sent> sent;
    SendStatus answer = SendStatus::Queued;

private:
    core::EventLoop& loop_;
};

CandumpRecord logged(std::chrono::microseconds time, std::string interface_name, std::uint32_t id) {
    return {TraceTime(1436509052s + time), std::move(interface_name),
            Frame::data_frame(id, {0x01})};
}

TEST(CandumpReplay, KeepsTheRelativeTimingOfTheLog) {
    core::EventLoop loop;
    RecordingPort port(loop);
    loop.run_until(core::TimePoint(5s));
    CandumpReplay replay(loop, port,
                         {logged(100us, "can0", 0x181), logged(1100us, "can0", 0x182),
                          logged(1100us, "can0", 0x183), logged(11100us, "can0", 0x184)});
    loop.run();
    ASSERT_EQ(port.sent.size(), 4U);
    EXPECT_EQ(port.sent[0].time, core::TimePoint(5s));
    EXPECT_EQ(port.sent[1].time, core::TimePoint(5s + 1ms));
    EXPECT_EQ(port.sent[2].time, core::TimePoint(5s + 1ms));
    EXPECT_EQ(port.sent[2].frame.id, 0x183U);
    EXPECT_EQ(port.sent[3].time, core::TimePoint(5s + 11ms));
    EXPECT_TRUE(replay.finished());
    EXPECT_EQ(replay.report().sent, 4U);
}

TEST(CandumpReplay, StartsAtTheGivenTime) {
    core::EventLoop loop;
    RecordingPort port(loop);
    CandumpReplay replay(loop, port, {logged(0us, "can0", 0x181), logged(500us, "can0", 0x182)},
                         {.start = core::TimePoint(2s)});
    loop.run();
    ASSERT_EQ(port.sent.size(), 2U);
    EXPECT_EQ(port.sent[0].time, core::TimePoint(2s));
    EXPECT_EQ(port.sent[1].time, core::TimePoint(2s + 500us));
}

TEST(CandumpReplay, PlaysOnlyTheChosenInterfaceTimedFromItsFirstFrame) {
    core::EventLoop loop;
    RecordingPort port(loop);
    CandumpReplay replay(loop, port,
                         {logged(0us, "can0", 0x181), logged(300us, "can1", 0x281),
                          logged(700us, "can1", 0x282), logged(800us, "can0", 0x182)},
                         {.interface_name = "can1"});
    loop.run();
    ASSERT_EQ(port.sent.size(), 2U);
    EXPECT_EQ(port.sent[0].frame.id, 0x281U);
    EXPECT_EQ(port.sent[0].time, core::TimePoint(0s));
    EXPECT_EQ(port.sent[1].time, core::TimePoint(400us));
    EXPECT_EQ(replay.report().sent, 2U);
    EXPECT_EQ(replay.report().skipped, 2U);
}

TEST(CandumpReplay, SkipsErrorFramesBecauseNoPortSendsThem) {
    core::EventLoop loop;
    RecordingPort port(loop);
    CandumpRecord error_frame = logged(10us, "can0", 0x08);
    error_frame.frame.error = true;
    CandumpReplay replay(loop, port, {logged(0us, "can0", 0x181), error_frame});
    loop.run();
    EXPECT_EQ(port.sent.size(), 1U);
    EXPECT_EQ(replay.report().skipped, 1U);
}

TEST(CandumpReplay, CountsFramesThePortRefuses) {
    core::EventLoop loop;
    RecordingPort port(loop);
    port.answer = SendStatus::BusOff;
    CandumpReplay replay(loop, port, {logged(0us, "can0", 0x181), logged(10us, "can0", 0x182)});
    loop.run();
    EXPECT_EQ(replay.report().sent, 0U);
    EXPECT_EQ(replay.report().refused, 2U);
    EXPECT_TRUE(replay.finished());
}

TEST(CandumpReplay, ReportsTheEndFromTheLoop) {
    core::EventLoop loop;
    RecordingPort port(loop);
    std::optional<core::TimePoint> finished_at;
    CandumpReplay replay(loop, port, {logged(0us, "can0", 0x181), logged(3ms, "can0", 0x182)},
                         {.on_finished = [&](const ReplayReport& report) {
                             EXPECT_EQ(report.sent, 2U);
                             finished_at = loop.now();
                         }});
    loop.run();
    EXPECT_EQ(finished_at, core::TimePoint(3ms));
}

TEST(CandumpReplay, EmptyLogFinishesWithoutSending) {
    core::EventLoop loop;
    RecordingPort port(loop);
    bool called = false;
    CandumpReplay replay(loop, port, {}, {.on_finished = [&](const ReplayReport&) {
                             called = true;
                         }});
    EXPECT_FALSE(called) << "must not run inside the constructor";
    loop.run();
    EXPECT_TRUE(called);
    EXPECT_TRUE(port.sent.empty());
}

TEST(CandumpReplay, DestroyingTheReplayStopsIt) {
    core::EventLoop loop;
    RecordingPort port(loop);
    {
        CandumpReplay replay(loop, port, {logged(0us, "can0", 0x181), logged(1s, "can0", 0x182)});
        loop.run_for(500ms);
    }
    loop.run();
    EXPECT_EQ(port.sent.size(), 1U);
}

} // namespace
} // namespace eposp::can
