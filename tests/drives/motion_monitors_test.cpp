#include "eposp/drives/motion/device_error_codes.hpp"
#include "eposp/drives/motion/following_error_monitor.hpp"
#include "eposp/drives/motion/sensor_direction_monitor.hpp"
#include "eposp/drives/motion/software_position_limit.hpp"
#include "eposp/drives/motion/standstill_monitor.hpp"
#include "eposp/drives/motion/target_reached_monitor.hpp"
#include "eposp/drives/motion/window_timer.hpp"

#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vector>

namespace eposp::drives::motion {
namespace {

/// One control period fed to a target reached monitor and what bit 10 must read after it.
struct Sample {
    double t;
    bool trajectory_ended;
    double actual;
    bool reached;
};

struct WindowCase {
    std::string name;
    TargetWindow window;
    double target;
    std::vector<Sample> samples;
};

// Position Window 0x6067 / Position Window Time 0x6068 (5.3, figure 5-7); the same rules hold
// for Velocity Window 0x606D / 0x606E (5.10, figure 5-33).
const WindowCase kWindowCases[] = {
    {"ReachedAfterWindowTimeInside",
     {10, 5},
     1000,
     {{0.000, true, 1008, false},
      {0.004, true, 1003, false},
      {0.005, true, 995, true},
      {0.006, true, 1000, true}}},
    {"LeavingBeforeWindowTimeStartsAgain",
     {10, 5},
     1000,
     {{0.000, true, 1005, false},
      {0.003, true, 1011, false},
      {0.004, true, 1005, false},
      {0.008, true, 1005, false},
      {0.009, true, 1005, true}}},
    {"LeavingAfterReachedClearsTheBit",
     {10, 2},
     1000,
     {{0.000, true, 1000, false}, {0.002, true, 1000, true}, {0.003, true, 1020, false}}},
    {"EdgeOfTheWindowIsInside",
     {10, 0},
     1000,
     {{0.000, true, 990, true}, {0.001, true, 1010, true}}},
    {"NotWhileTheTrajectoryRuns",
     {10, 0},
     1000,
     {{0.000, false, 1000, false}, {0.001, false, 1000, false}, {0.002, true, 1000, true}}},
    {"SwitchedOffFollowsTheTrajectoryEnd",
     {kWindowSwitchedOff, 500},
     1000,
     {{0.000, false, 0, false}, {0.001, true, -50000, true}}},
    {"VelocityWindowAroundTheTargetVelocity",
     {20, 3},
     -3000,
     {{0.000, true, -2985, false}, {0.003, true, -3019, true}, {0.004, true, -2979, false}}},
};

class TargetReached : public ::testing::TestWithParam<WindowCase> {};

TEST_P(TargetReached, FollowsWindowAndWindowTime) {
    const WindowCase& c = GetParam();
    TargetReachedMonitor monitor(c.window);
    for (const Sample& s : c.samples) {
        EXPECT_EQ(monitor.update(s.t, s.trajectory_ended, s.actual, c.target), s.reached)
            << "t = " << s.t;
    }
}

INSTANTIATE_TEST_SUITE_P(Windows, TargetReached, ::testing::ValuesIn(kWindowCases),
                         [](const auto& row) { return row.param.name; });

TEST(WindowTimer, ResetStartsTheTimeAgain) {
    WindowTimer timer(0.002);
    EXPECT_FALSE(timer.update(0.000, true));
    timer.reset();
    EXPECT_FALSE(timer.update(0.001, true));
    EXPECT_FALSE(timer.update(0.002, true));
    EXPECT_TRUE(timer.update(0.003, true));
}

struct FollowingRow {
    std::uint32_t max;
    double demand;
    double actual;
    bool active;
    bool raised;
};

TEST(FollowingError, RaisedOnceWhenTheMaximumIsExceeded) {
    // One monitor, one row per control period.
    const FollowingRow rows[] = {
        {2000, 0, 0, false, false},       {2000, 5000, 3000, false, false},
        {2000, 5000, 2999, true, true},   {2000, 6000, 1000, true, false},
        {2000, -100, 1900, false, false}, {2000, -100, 1901, true, true},
    };
    FollowingErrorMonitor monitor(2000);
    for (const FollowingRow& row : rows) {
        const auto raised = monitor.update(row.demand, row.actual);
        EXPECT_EQ(monitor.active(), row.active) << row.demand << " " << row.actual;
        EXPECT_EQ(raised, row.raised ? std::optional<std::uint16_t>(0x8611) : std::nullopt);
    }
}

TEST(FollowingError, MaximumOf2To32Minus1SwitchesTheControlOff) {
    FollowingErrorMonitor monitor(kFollowingControlOff);
    EXPECT_FALSE(monitor.update(1e12, -1e12));
    EXPECT_FALSE(monitor.active());
}

TEST(FollowingError, DefaultMaximumIs2000) {
    FollowingErrorMonitor monitor;
    EXPECT_FALSE(monitor.update(2000, 0));
    EXPECT_EQ(monitor.update(2001, 0), kFollowingErrorCode);
}

constexpr std::int32_t kOffMin = std::numeric_limits<std::int32_t>::min();
constexpr std::int32_t kOffMax = std::numeric_limits<std::int32_t>::max();

struct LimitRow {
    SoftwarePositionLimit limit;
    double position;
    bool allowed;
    double clamped;
};

TEST(SoftwarePositionLimit, TargetsAreCheckedAndClampedPerTable) {
    const LimitRow rows[] = {
        {{-1000, 1000}, 0, true, 0},
        {{-1000, 1000}, 1000, true, 1000},
        {{-1000, 1000}, 1001, false, 1000},
        {{-1000, 1000}, -1001, false, -1000},
        {{kOffMin, 1000}, -5e9, true, -5e9}, // the minimum switched off
        {{-1000, kOffMax}, 5e9, true, 5e9},  // the maximum switched off
        {{}, 1e12, true, 1e12},              // defaults: both off
    };
    for (const LimitRow& row : rows) {
        EXPECT_EQ(row.limit.allows(row.position), row.allowed) << row.position;
        EXPECT_EQ(row.limit.clamp(row.position), row.clamped) << row.position;
        EXPECT_EQ(row.limit.check_target(row.position),
                  row.allowed ? std::nullopt : std::optional<std::uint16_t>(0xFF09));
    }
}

TEST(SoftwarePositionLimit, ActualPositionOutsideRaisesOncePerExcursion) {
    SoftwarePositionLimitMonitor monitor({-1000, 1000});
    EXPECT_FALSE(monitor.update(999));
    EXPECT_EQ(monitor.update(1001), kSoftwarePositionLimitErrorCode);
    EXPECT_FALSE(monitor.update(1500));
    EXPECT_TRUE(monitor.active());
    EXPECT_FALSE(monitor.update(0));
    EXPECT_FALSE(monitor.active());
    EXPECT_EQ(monitor.update(-1001), kSoftwarePositionLimitErrorCode);
}

TEST(Standstill, SpeedZeroAfterStandstillWindowTime) {
    StandstillMonitor monitor({30, 50, 1000});
    EXPECT_FALSE(monitor.update(0.000, 31, false));
    EXPECT_FALSE(monitor.update(0.001, 30, false));
    EXPECT_FALSE(monitor.update(0.050, -12, false));
    EXPECT_TRUE(monitor.update(0.051, 0, false));
    EXPECT_FALSE(monitor.update(0.052, -31, false));
}

TEST(Standstill, SwitchedOffWindowMeansTheEndOfTheTrajectory) {
    StandstillMonitor monitor({kStandstillSwitchedOff, 50, 1000});
    EXPECT_FALSE(monitor.update(0.0, 0, false));
    EXPECT_TRUE(monitor.update(0.001, 500, true));
}

TEST(Standstill, StopCompletesAtStandstillOrAfterTheTimeout) {
    StandstillMonitor monitor({30, 50, 1000});
    monitor.stop_started(1.0);
    monitor.update(1.5, 800, false);
    EXPECT_FALSE(monitor.stop_completed(1.5));
    EXPECT_TRUE(monitor.stop_completed(2.0)); // "prevents hangs" (8.2.73 sub 3)

    StandstillMonitor settling({30, 50, 1000});
    settling.stop_started(0.0);
    settling.update(0.10, 0, false);
    settling.update(0.15, 0, false);
    EXPECT_TRUE(settling.stop_completed(0.15));

    StandstillMonitor no_timeout({30, 50, kStandstillSwitchedOff});
    no_timeout.stop_started(0.0);
    no_timeout.update(100, 800, false);
    EXPECT_FALSE(no_timeout.stop_completed(100));
}

// EPOS2 FW spec 4.2.37: the sensor counting against the motor's turning `limit` counts in a row
// is the error; a count with the motor, a motor at rest or no supervision starts the count over.
TEST(SensorDirectionMonitor, CountsAgainstTheMotorInARowAreTheError) {
    SensorDirectionMonitor monitor(10, 100);
    EXPECT_FALSE(monitor.update(5.0, 106)) << "with the motor";
    EXPECT_FALSE(monitor.update(5.0, 100)) << "6 against";
    EXPECT_FALSE(monitor.update(5.0, 100)) << "no count: still 6";
    EXPECT_FALSE(monitor.update(5.0, 101)) << "with the motor again: over";
    EXPECT_FALSE(monitor.update(5.0, 95));
    EXPECT_FALSE(monitor.update(0.0, 91)) << "the motor at rest (or unwatched): over";
    EXPECT_FALSE(monitor.update(-5.0, 95));
    EXPECT_FALSE(monitor.update(-5.0, 100)) << "9 against a motor turning negative";
    EXPECT_TRUE(monitor.update(-5.0, 101)) << "10";
    EXPECT_TRUE(monitor.update(-5.0, 101)) << "while it lasts";
    EXPECT_FALSE(monitor.update(0.0, 120));
}

} // namespace
} // namespace eposp::drives::motion
