// The drive's physics run on its own schedule, not on the host's load: a 1000 rpm profile move
// gives the same Position / Velocity Actual Values (0x6064 / 0x606C) every millisecond whether
// its event loop keeps time or runs late in bursts (real-time pace on a loaded host, where an
// I/O handler meanwhile reads the wall clock), commanded through the dictionary or by RPDO, and
// the reference axis does not overshoot.
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"

#include <algorithm>
#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <chrono>
#include <functional>
#include <gtest/gtest.h>
#include <optional>
#include <ostream>
#include <vector>

namespace eposp::drives::epos2 {
namespace {

using namespace std::chrono_literals;

struct Sample {
    std::int32_t position; ///< 0x6064, qc
    std::int32_t velocity; ///< 0x606C, rpm
    friend bool operator==(const Sample&, const Sample&) = default;
    friend void PrintTo(const Sample& sample, std::ostream* out) {
        *out << sample.position << " qc, " << sample.velocity << " rpm";
    }
};

// The move starts 50 ms after the drive is built, at `kOrigin` on both loops, so that both runs
// see the same absolute times.
constexpr core::TimePoint kOrigin{100ms};
constexpr auto kMoveStart = 50ms;
constexpr auto kEnd = 450ms;
constexpr std::uint32_t kRpdo1Id = 0x202; // node 2
constexpr std::uint32_t kRpdo3Id = 0x402;

/// How the master commands the drive: writing the dictionary as its SDO writes would, or by
/// RPDO frames on the bus (3: controlword and target, 1: controlword; 8.2.18, 8.2.20).
enum class Commands { Dictionary, Rpdo };

/// A master commanding the reference axis (1000 rpm, 10 000 rpm/s, four turns), and the values
/// it samples each millisecond. `disturb` runs at the given times into the move.
std::vector<Sample> profile_move(core::EventLoop& loop, const std::function<void()>& disturb,
                                 const std::vector<core::Duration>& disturbances,
                                 Commands commands = Commands::Dictionary) {
    can::VirtualBus bus{loop};
    const std::unique_ptr<can::VirtualPort> port = bus.connect("epos2");
    // The master; also, a node alone on the bus sees no acknowledgement and goes error-passive
    // (0x8120, 4.2.15).
    const std::unique_ptr<can::VirtualPort> master = bus.connect("master");
    std::optional<Epos2Drive> drive;
    std::vector<Sample> samples;
    std::vector<core::ScopedTimer> timers;
    const auto at = [&](core::Duration after, std::function<void()> fn) {
        timers.emplace_back(loop, loop.at(kOrigin + after, std::move(fn)));
    };
    const auto write = [&drive](std::uint16_t index, auto value) {
        ASSERT_EQ(drive->objects().write(index, 0, canopen::encode(value)),
                  canopen::AbortCode::None);
    };
    const auto command = [&](std::uint16_t controlword, std::optional<std::int32_t> target = {}) {
        if (commands == Commands::Dictionary) {
            if (target) {
                write(0x607A, *target);
            }
            write(0x6040, controlword);
            return;
        }
        std::vector<std::uint8_t> data{static_cast<std::uint8_t>(controlword),
                                       static_cast<std::uint8_t>(controlword >> 8)};
        if (target) {
            const canopen::Bytes bytes = canopen::encode(*target);
            data.insert(data.end(), bytes.begin(), bytes.end());
        }
        master->send(can::Frame::data_frame(target ? kRpdo3Id : kRpdo1Id, data));
    };
    at(0ms, [&] {
        Epos2DriveConfig config;
        config.dictionary.node_id = 2;
        drive.emplace(loop, *port, std::move(config));
        drive->start();
    });
    at(10ms, [&] {
        write(0x6081, std::uint32_t{1000});
        write(0x6083, std::uint32_t{10'000});
        write(0x6084, std::uint32_t{10'000});
        master->send(can::Frame::data_frame(canopen::kNmtCanId, {0x01, 0x02})); // start node 2
    });
    at(15ms, [&] { command(0x0006); }); // shutdown
    at(20ms, [&] { command(0x000F); }); // switch on, enable operation
    // Four turns of the 500-pulse encoder; new set-point, absolute, at once.
    at(kMoveStart, [&] { command(0x003F, 4 * 2000); });
    at(kMoveStart + 20ms, [&] { command(0x000F); });
    for (const core::Duration when : disturbances) {
        at(kMoveStart + when, disturb);
    }
    timers.emplace_back(loop, loop.every(1ms, kOrigin + kMoveStart + 500us, [&] {
        samples.push_back({drive->objects().get_as<std::int32_t>(0x6064, 0),
                           drive->objects().get_as<std::int32_t>(0x606C, 0)});
    }));
    loop.run_until(kOrigin + kEnd);
    return samples;
}

// The host is busy for 5 ms at `late` (a real-time loop); meanwhile a frame arrives from a
// socket, whose handler reads the clock.
std::function<void()> busy_host(core::EventLoop& late) {
    return [&late] {
        const auto until = std::chrono::steady_clock::now() + 5ms;
        while (std::chrono::steady_clock::now() < until) {
        }
        boost::asio::post(late.io(), [&late] { (void)late.now(); });
    };
}

void expect_same_samples(const std::vector<Sample>& disturbed,
                         const std::vector<Sample>& undisturbed) {
    ASSERT_EQ(disturbed.size(), undisturbed.size());
    for (std::size_t ms = 0; ms < undisturbed.size(); ++ms) {
        ASSERT_EQ(disturbed[ms], undisturbed[ms]) << "at " << ms << " ms into the move";
    }
}

TEST(Epos2DriveClock, LateBurstsOfTheLoopGiveTheSamplesOfAnUndisturbedRun) {
    core::EventLoop on_time;
    const std::vector<Sample> undisturbed = profile_move(on_time, [] {}, {});

    // Accelerating, cruising, decelerating.
    core::EventLoop late(core::Pace::RealTime);
    expect_same_samples(profile_move(late, busy_host(late), {50ms, 150ms, 280ms}), undisturbed);
}

// The same with the commands by RPDO: the host is busy while the frame that starts the move is
// on the bus, and the loop, late, hears it with the wall clock read. Its controlword still acts
// at the control period after the frame's time, not at the wall clock's.
TEST(Epos2DriveClock, AnRpdoHeardLateActsAtTheControlPeriodOfItsTime) {
    core::EventLoop on_time;
    const std::vector<Sample> undisturbed = profile_move(
        on_time, [] {}, {}, Commands::Rpdo);
    ASSERT_NEAR(undisturbed.back().position, 8000, 10) << "the RPDOs moved the axis";

    core::EventLoop late(core::Pace::RealTime);
    expect_same_samples(profile_move(late, busy_host(late), {10us, 150ms}, Commands::Rpdo),
                        undisturbed);
}

// The reference axis (`eposp drive epos2` without --config) follows a 1000 rpm profile without
// overshoot beyond the 1 ms velocity measurement's resolution (one quadcount per millisecond is
// 30 rpm at 2000 qc per turn).
TEST(Epos2DriveClock, ReferenceAxisFollows1000RpmWithoutOvershoot) {
    core::EventLoop loop;
    const std::vector<Sample> samples = profile_move(loop, [] {}, {});
    const auto peak = std::ranges::max(samples, {}, &Sample::velocity).velocity;
    EXPECT_GE(peak, 1000);
    EXPECT_LE(peak, 1030);
    EXPECT_NEAR(samples.back().position, 8000, 10); // at rest in the target's window
}

} // namespace
} // namespace eposp::drives::epos2
