#include "eposp/drives/motion/profile_planner.hpp"
#include "eposp/drives/motion/profile_position_generator.hpp"
#include "eposp/drives/motion/profile_velocity_generator.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace eposp::drives::motion {
namespace {

constexpr double kTight = 1e-9;

ProfileParameters linear(double v, double a, double d) {
    return {v, a, d, RampShape::Linear};
}
ProfileParameters sin2(double v, double a, double d) {
    return {v, a, d, RampShape::SinSquared};
}

double peak_velocity(const Trajectory& trajectory) {
    double peak = 0;
    for (const RampSegment& segment : trajectory.segments()) {
        peak = std::max({peak, std::abs(segment.v_start), std::abs(segment.v_end)});
    }
    return peak;
}

// Samples finely and checks that position and velocity never jump and the end is at rest on
// the target.
void expect_continuous_to(const Trajectory& trajectory, double target) {
    constexpr double kStep = 1e-4;
    MotionState previous = trajectory.sample(0);
    for (double t = kStep; t < trajectory.duration() + 2 * kStep; t += kStep) {
        const MotionState now = trajectory.sample(t);
        const double max_v = std::max(std::abs(previous.velocity), std::abs(now.velocity));
        ASSERT_NEAR(now.position, previous.position, max_v * kStep * 1.01 + 1e-9) << t;
        ASSERT_NEAR(now.velocity, previous.velocity,
                    std::max(std::abs(previous.acceleration), std::abs(now.acceleration)) * kStep *
                            1.01 +
                        1e-6)
            << t;
        previous = now;
    }
    EXPECT_NEAR(trajectory.final_position(), target, 1e-6);
    EXPECT_NEAR(trajectory.sample(trajectory.duration() + 1).velocity, 0, kTight);
}

TEST(ProfilePosition, TrapezoidMoveTimeAndPeakVelocityMatchClosedForm) {
    // t = D/v + v/(2a) + v/(2d) = 10 + 0.25 + 0.125
    const Trajectory move = plan_position_move({}, 10000, linear(1000, 2000, 4000));
    EXPECT_NEAR(move.duration(), 10.375, kTight);
    EXPECT_NEAR(peak_velocity(move), 1000, kTight);
    EXPECT_NEAR(move.sample(0.25).acceleration, 2000, kTight);
    EXPECT_NEAR(move.sample(10.3).acceleration, -4000, kTight);
    EXPECT_NEAR(move.sample(0.5).position, 250, kTight); // area of the acceleration triangle
    expect_continuous_to(move, 10000);
}

TEST(ProfilePosition, TriangularWhenProfileVelocityIsNotReached) {
    // a = d: vp = √(D·a), t = 2·vp/a
    const Trajectory move = plan_position_move({}, 100, linear(1000, 1000, 1000));
    EXPECT_NEAR(peak_velocity(move), std::sqrt(1e5), 1e-9);
    EXPECT_NEAR(move.duration(), 2 * std::sqrt(1e5) / 1000, kTight);
    expect_continuous_to(move, 100);
}

TEST(ProfilePosition, NegativeMoveMirrorsPositiveOne) {
    const Trajectory move = plan_position_move({500, 0, 0}, -9500, linear(1000, 2000, 4000));
    EXPECT_NEAR(move.duration(), 10.375, kTight);
    EXPECT_NEAR(move.sample(5).velocity, -1000, kTight);
    expect_continuous_to(move, -9500);
}

TEST(ProfilePosition, SinSquaredRampsTakeTwiceAsLongWithProfileAccelerationAsPeak) {
    // Figure 5-9: Amax is the profile acceleration; ramp T = 2v/A, t = D/v + v/a + v/d.
    const Trajectory move = plan_position_move({}, 10000, sin2(1000, 2000, 4000));
    EXPECT_NEAR(move.duration(), 10 + 0.5 + 0.25, kTight);
    EXPECT_NEAR(move.sample(0.5).acceleration, 2000, 1e-6); // mid-ramp peak
    EXPECT_NEAR(move.sample(0).acceleration, 0, kTight);    // jerk-limited start
    EXPECT_NEAR(move.sample(1.0).position, 500, 1e-9);      // ramp area v·T/2
    expect_continuous_to(move, 10000);
}

TEST(ProfilePosition, SinSquaredTriangularPeakVelocity) {
    // k = 2, a = d: vp = √(D·a/2)
    const Trajectory move = plan_position_move({}, 200, sin2(1000, 1000, 1000));
    EXPECT_NEAR(peak_velocity(move), std::sqrt(200 * 1000 / 2.0), 1e-9);
    EXPECT_NEAR(move.duration(), 4 * std::sqrt(1e5) / 1000, 1e-9);
    expect_continuous_to(move, 200);
}

TEST(ProfilePosition, ReplanningBackwardsStopsThenReverses) {
    const Trajectory first = plan_position_move({}, 10000, linear(1000, 2000, 2000));
    const MotionState moving = first.sample(3);
    const Trajectory second = plan_position_move(moving, 0, linear(1000, 2000, 2000));
    EXPECT_NEAR(second.sample(0).position, moving.position, kTight);
    EXPECT_NEAR(second.sample(0).velocity, moving.velocity, kTight);
    // stop in 0.5 s, then 2750 + 250 qc back at full profile: 0.5 + 3.25 + 0.5
    EXPECT_NEAR(second.duration(), 0.5 + 0.5 + (3000 - 500) / 1000.0 + 0.5, kTight);
    expect_continuous_to(second, 0);
}

TEST(ProfilePosition, ReplanningTooCloseToStopOvershootsAndComesBack) {
    const MotionState moving{0, 1000, 0};
    const Trajectory move = plan_position_move(moving, 100, linear(1000, 2000, 2000));
    EXPECT_NEAR(move.sample(0.5).position, 250, kTight); // stopping distance v²/2d
    expect_continuous_to(move, 100);
}

TEST(ProfilePosition, ReplanningForwardKeepsMovingWithoutStopping) {
    const MotionState moving{0, 500, 0};
    const Trajectory move = plan_position_move(moving, 5000, linear(1000, 1000, 1000));
    // 0.5 s up to 1000 (375 qc), cruise, 1 s down (500 qc)
    EXPECT_NEAR(move.duration(), 0.5 + (5000 - 375 - 500) / 1000.0 + 1.0, kTight);
    expect_continuous_to(move, 5000);
}

TEST(ProfilePosition, LoweredMaxVelocityWhileMovingSlowsDownToIt) {
    const MotionState moving{0, 2000, 0};
    const Trajectory move = plan_position_move(moving, 10000, linear(1000, 1000, 1000));
    EXPECT_NEAR(move.sample(1.0).velocity, 1000, kTight);
    expect_continuous_to(move, 10000);
}

TEST(ProfilePosition, ClampsToMaxProfileVelocityAndMaxAcceleration) {
    const auto clamped = clamp_to_limits(linear(5000, 100000, 500), ProfileLimits{3000, 20000});
    ASSERT_TRUE(clamped.ok());
    EXPECT_EQ(clamped->velocity, 3000);
    EXPECT_EQ(clamped->acceleration, 20000);
    EXPECT_EQ(clamped->deceleration, 500);
}

TEST(ProfilePosition, ZeroParametersAreRefused) {
    EXPECT_FALSE(clamp_to_limits(linear(0, 1, 1), ProfileLimits{1, 1}).ok());
    EXPECT_FALSE(clamp_to_limits(linear(1, 1, 0), ProfileLimits{1, 1}).ok());
    EXPECT_FALSE(clamp_to_limits(linear(1, 1, 1), ProfileLimits{0, 1}).ok());
}

TEST(ProfileVelocity, AccelerationRampTimeAndArea) {
    const Trajectory ramp = plan_velocity_change({}, 3000, linear(0, 1000, 500));
    EXPECT_NEAR(ramp.duration(), 3, kTight);
    EXPECT_NEAR(ramp.sample(3).position, 4500, kTight);
    EXPECT_NEAR(ramp.sample(10).velocity, 3000, kTight); // held after the ramp
}

TEST(ProfileVelocity, ReversalDeceleratesThroughZeroThenAccelerates) {
    const Trajectory ramp = plan_velocity_change({0, 1000, 0}, -2000, linear(0, 1000, 500));
    EXPECT_NEAR(ramp.duration(), 2 + 2, kTight);
    EXPECT_NEAR(ramp.sample(2).velocity, 0, kTight);
    EXPECT_NEAR(ramp.sample(1).acceleration, -500, kTight);
    EXPECT_NEAR(ramp.sample(3).acceleration, -1000, kTight);
}

TEST(ProfileVelocity, SinSquaredSlowDownUsesDeceleration) {
    const Trajectory ramp = plan_velocity_change({0, 1000, 0}, 200, sin2(0, 1000, 400));
    EXPECT_NEAR(ramp.duration(), 2 * 800 / 400.0, kTight);
    EXPECT_NEAR(ramp.sample(2).acceleration, -400, 1e-9);
}

TEST(ProfilePositionGenerator, BufferedSetpointStartsWhenTheFirstMoveEnds) {
    ProfilePositionGenerator generator;
    const ProfileParameters p = linear(1000, 1000, 1000);
    ASSERT_TRUE(generator.new_setpoint(0, {1000, false, p}, false)); // 2 s
    ASSERT_TRUE(generator.new_setpoint(0.1, {500, true, p}, false));
    EXPECT_TRUE(generator.buffer_full());
    EXPECT_FALSE(generator.new_setpoint(0.2, {0, false, p}, false)); // no room: not acknowledged
    EXPECT_NEAR(generator.update(2.0).position, 1000, kTight);
    // The relative setpoint counts from the first target: 500 qc triangular, 2·√0.5 s.
    const double second = 2 * std::sqrt(0.5);
    EXPECT_GT(generator.update(2.0 + second / 2).position, 1000);
    EXPECT_FALSE(generator.buffer_full());
    EXPECT_NEAR(generator.update(2.0 + second).position, 1500, 1e-9);
    EXPECT_TRUE(generator.finished(2.0 + second));
}

TEST(ProfilePositionGenerator, ChangeSetImmediatelyReplansFromTheMovingState) {
    ProfilePositionGenerator generator;
    const ProfileParameters p = linear(1000, 1000, 1000);
    generator.new_setpoint(0, {10000, false, p}, true);
    const MotionState before = generator.update(2);
    generator.new_setpoint(2, {-1000, false, p}, true);
    const MotionState after = generator.update(2);
    EXPECT_NEAR(after.position, before.position, kTight);
    EXPECT_NEAR(after.velocity, before.velocity, kTight);
    EXPECT_NEAR(generator.update(100).position, -1000, 1e-9);
}

TEST(ProfilePositionGenerator, HaltStopsWithProfileDecelerationAndResumes) {
    ProfilePositionGenerator generator;
    generator.new_setpoint(0, {10000, false, linear(1000, 1000, 2000)}, true);
    const MotionState cruising = generator.update(3);
    generator.set_halt(3, true);
    const double stopped = generator.update(10).position;
    EXPECT_NEAR(stopped, cruising.position + 1000.0 * 1000 / (2 * 2000), kTight);
    EXPECT_TRUE(generator.finished(10));
    generator.set_halt(10, false);
    EXPECT_NEAR(generator.update(30).position, 10000, 1e-9);
}

TEST(ProfilePositionGenerator, QuickStopUsesQuickStopDecelerationAndDropsSetpoints) {
    ProfilePositionGenerator generator;
    const ProfileParameters p = linear(1000, 1000, 1000);
    generator.new_setpoint(0, {10000, false, p}, true);
    generator.new_setpoint(0, {0, false, p}, false);
    const MotionState cruising = generator.update(3);
    generator.quick_stop(3, 10000, RampShape::Linear);
    EXPECT_FALSE(generator.buffer_full());
    EXPECT_NEAR(generator.update(3.1).position, cruising.position + 50, kTight);
    EXPECT_NEAR(generator.update(50).position, cruising.position + 50, kTight);
}

TEST(ProfilePositionGenerator, EndlessMovementRunsAtProfileVelocityInTheTargetsDirection) {
    ProfilePositionGenerator generator;
    const ProfileParameters p = linear(1000, 1000, 1000);
    generator.new_setpoint(0, {-1, false, p, true}, true);
    EXPECT_NEAR(generator.update(100).velocity, -1000, kTight);
    EXPECT_FALSE(generator.finished(100));
    EXPECT_TRUE(generator.new_setpoint(100, {0, false, p}, false)); // waits: never "finished"
    EXPECT_NEAR(generator.update(200).velocity, -1000, kTight);
    generator.set_halt(200, true);
    EXPECT_NEAR(generator.update(201).velocity, 0, kTight);
}

TEST(ProfileVelocityGenerator, NewTargetRampsFromThePresentDemand) {
    ProfileVelocityGenerator generator;
    const ProfileParameters p = linear(0, 1000, 500);
    generator.set_target(0, 2000, p);
    const MotionState mid_ramp = generator.update(1);
    generator.set_target(1, 0, p);
    EXPECT_NEAR(generator.update(1).velocity, mid_ramp.velocity, kTight);
    EXPECT_NEAR(generator.update(1).position, mid_ramp.position, kTight);
    EXPECT_FALSE(generator.ramp_finished(2.9));
    EXPECT_TRUE(generator.ramp_finished(3)); // 1000 down at 500/s
    EXPECT_NEAR(generator.update(3).position, 500 + 1000, kTight);
}

TEST(ProfileVelocityGenerator, HaltStopsWithProfileDecelerationAndReleaseResumes) {
    ProfileVelocityGenerator generator;
    const ProfileParameters p = linear(0, 1000, 500);
    generator.set_target(0, 1000, p);
    generator.set_halt(5, true);
    EXPECT_NEAR(generator.update(6).velocity, 500, kTight);
    EXPECT_NEAR(generator.update(7).velocity, 0, kTight);
    generator.set_halt(7, false);
    EXPECT_NEAR(generator.update(8).velocity, 1000, kTight);
}

TEST(ProfileVelocityGenerator, QuickStopUsesItsOwnDeceleration) {
    ProfileVelocityGenerator generator;
    generator.set_target(0, -1000, linear(0, 1000, 500));
    generator.quick_stop(2, 10000);
    EXPECT_NEAR(generator.update(2.1).velocity, 0, kTight);
    EXPECT_NEAR(generator.update(5).position, generator.update(2.1).position, kTight);
}

} // namespace
} // namespace eposp::drives::motion
