// The real-time pace is the one place where the wall clock is the point of the test; the waits
// here are a few milliseconds of the loop's own blocking, never a sleep.
#include "eposp/core/event_loop.hpp"

#include <array>
#include <boost/asio/io_context.hpp>
#include <boost/asio/local/connect_pair.hpp>
#include <boost/asio/local/stream_protocol.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <gtest/gtest.h>
#include <thread>

namespace eposp::core {
namespace {

using namespace std::chrono_literals;
using WallClock = std::chrono::steady_clock;

TEST(RealTimeLoop, TimerWaitsForTheWallClock) {
    EventLoop loop(Pace::RealTime);
    const auto wall_start = WallClock::now();
    const TimePoint start = loop.now();
    TimePoint fired{};
    loop.at(start + 20ms, [&] { fired = loop.now(); });
    loop.run_for(25ms);
    EXPECT_EQ(fired, start + 20ms); // the callback sees its scheduled time
    EXPECT_GE(WallClock::now() - wall_start, 25ms);
    EXPECT_GE(loop.now(), start + 25ms);
}

TEST(RealTimeLoop, PeriodicTimerKeepsItsScheduleInRealTime) {
    EventLoop loop(Pace::RealTime);
    const TimePoint start = loop.now();
    std::vector<TimePoint> ticks;
    loop.every(2ms, start + 2ms, [&] { ticks.push_back(loop.now()); });
    loop.run_until(start + 21ms);
    ASSERT_EQ(ticks.size(), 10U);
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        EXPECT_EQ(ticks[i], start + 2ms * static_cast<int>(i + 1));
    }
}

TEST(RealTimeLoop, FileDescriptorHandlersRunWhileNoEventIsDue) {
    EventLoop loop(Pace::RealTime);
    boost::asio::local::stream_protocol::socket reader(loop.io());
    boost::asio::local::stream_protocol::socket writer(loop.io());
    boost::asio::local::connect_pair(reader, writer);

    std::array<char, 4> buffer{};
    TimePoint received{};
    boost::asio::async_read(reader, boost::asio::buffer(buffer),
                            [&](boost::system::error_code ec, std::size_t) {
                                ASSERT_FALSE(ec);
                                received = loop.now();
                                loop.stop();
                            });
    loop.after(5ms, [&] { boost::asio::write(writer, boost::asio::buffer("ping", 4)); });
    loop.run_for(10s); // returns as soon as the handler stops the loop
    EXPECT_EQ(std::string(buffer.data(), buffer.size()), "ping");
    EXPECT_GE(received.time_since_epoch(), 5ms);
    EXPECT_LT(received.time_since_epoch(), 5s);
}

TEST(RealTimeLoop, StopFromAnotherThreadWakesABlockedLoop) {
    EventLoop loop(Pace::RealTime);
    std::thread stopper([&] {
        std::this_thread::sleep_for(10ms); // stands in for a signal arriving at some moment
        loop.stop();
    });
    const auto wall_start = WallClock::now();
    loop.run();
    stopper.join();
    EXPECT_LT(WallClock::now() - wall_start, 5s);
}

} // namespace
} // namespace eposp::core
