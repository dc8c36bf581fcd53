// Position Mode's demand (EPOS2 FW spec 5.6, table 5-37): the set value within Maximal Profile
// Velocity and Max Acceleration, one update per 1 ms control period.
#include "eposp/drives/motion/position_set_value_limiter.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace eposp::drives::motion {
namespace {

constexpr double kPeriod = 1e-3;

// A jump of 20 000 qc at v = 33 333 qc/s, a = 333 333 qc/s²: a trapezoid of 0.1 s ramps and
// 0.5 s cruise, on the set value without overshoot, never beyond v or a.
TEST(PositionSetValueLimiter, JumpIsApproachedAtMaxVelocityAndAccelerationWithoutOvershoot) {
    const double v = 33'333;
    const double a = 333'333;
    PositionSetValueLimiter limiter(0);
    double arrived = -1;
    for (int period = 1; period <= 1000; ++period) {
        const MotionState demand = limiter.update(20'000, v, a, kPeriod);
        ASSERT_LE(std::abs(demand.velocity), v + 1e-6) << period;
        ASSERT_LE(std::abs(demand.acceleration), a * 1.0001) << period;
        ASSERT_LE(demand.position, 20'000.01) << period; // less than a hundredth of a count
        if (arrived < 0 && demand.position == 20'000.0) {
            arrived = period * kPeriod;
        }
    }
    EXPECT_NEAR(arrived, v / a + 20'000 / v, 0.01);
    EXPECT_EQ(limiter.update(20'000, v, a, kPeriod).velocity, 0.0) << "at rest on it";
}

// A set value that moves within the limits (a master's own profile: 100 000 qc/s² for 0.1 s,
// then 10 000 qc/s) is the demand, exactly.
TEST(PositionSetValueLimiter, SetValueMovingWithinTheLimitsIsFollowedExactly) {
    PositionSetValueLimiter limiter(100);
    const auto profile = [](double t) {
        return t <= 0.1 ? 100 + 50'000 * t * t : 100 + 500 + 10'000 * (t - 0.1);
    };
    for (int period = 1; period <= 500; ++period) {
        const double set_value = profile(period * kPeriod);
        const MotionState demand = limiter.update(set_value, 33'333, 333'333, kPeriod);
        ASSERT_NEAR(demand.position, set_value, 1e-9) << period;
    }
    EXPECT_NEAR(limiter.update(profile(0.501), 33'333, 333'333, kPeriod).velocity, 10'000, 1e-6);
}

// A set value that keeps still is held, at rest.
TEST(PositionSetValueLimiter, SetValueAtTheStartIsHeldAtRest) {
    PositionSetValueLimiter limiter(-500);
    for (int period = 1; period <= 10; ++period) {
        const MotionState demand = limiter.update(-500, 1000, 1000, kPeriod);
        EXPECT_EQ(demand.position, -500);
        EXPECT_EQ(demand.velocity, 0);
    }
}

// A reversal of the set value brakes at the maximal acceleration, then turns.
TEST(PositionSetValueLimiter, ReversalBrakesAtMaxAccelerationFirst) {
    PositionSetValueLimiter limiter(0);
    for (int period = 1; period <= 200; ++period) {
        limiter.update(50'000, 33'333, 333'333, kPeriod);
    }
    MotionState demand = limiter.update(0, 33'333, 333'333, kPeriod);
    EXPECT_NEAR(demand.velocity, 33'333 - 333.333, 1e-3) << "one step slower, still forward";
    for (int period = 1; period <= 2000; ++period) {
        demand = limiter.update(0, 33'333, 333'333, kPeriod);
        ASSERT_LE(std::abs(demand.acceleration), 333'333 * 1.0001) << period;
    }
    EXPECT_EQ(demand.position, 0);
    EXPECT_EQ(demand.velocity, 0);
}

} // namespace
} // namespace eposp::drives::motion
