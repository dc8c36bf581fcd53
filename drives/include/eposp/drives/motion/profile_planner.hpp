#pragma once

#include "eposp/core/result.hpp"
#include "eposp/drives/motion/trajectory.hpp"

namespace eposp::drives::motion {

/// The commanding parameters of a profile (EPOS2 FW spec 5.3.2.2 / 5.10.2.2), in consistent units.
struct ProfileParameters {
    double velocity = 0;     ///< Profile Velocity 0x6081 (PPM); PVM takes its target separately
    double acceleration = 0; ///< Profile Acceleration 0x6083
    double deceleration = 0; ///< Profile Deceleration 0x6084
    RampShape shape = RampShape::Linear; ///< Motion Profile Type 0x6086
};

/// The configuration limits (5.3.2.1 / 5.10.2.1).
struct ProfileLimits {
    double max_velocity = 0;     ///< Maximal Profile Velocity 0x607F
    double max_acceleration = 0; ///< Max Acceleration 0x60C5
};

/// The parameters a profile really uses: velocity at most the max profile velocity, accelerations
/// at most the max acceleration. Non-positive values are an error (the generator cannot plan).
core::Result<ProfileParameters> clamp_to_limits(const ProfileParameters& parameters,
                                                const ProfileLimits& limits);

/// Profile Position (5.3.1): from any state (moving or not) to rest at `target`, accelerating
/// with `acceleration`, cruising at most at `velocity`, stopping with `deceleration`. When the
/// present velocity points away from the target or cannot stop before it, the move first stops
/// and then comes back. Position and velocity are continuous with `start`. Parameters must be
/// clamped (positive).
Trajectory plan_position_move(const MotionState& start, double target,
                              const ProfileParameters& parameters);

/// Profile Velocity (5.10.1): from any state to `target_velocity`, with the profile acceleration
/// when speeding up and the deceleration when slowing down (through zero on reversal).
Trajectory plan_velocity_change(const MotionState& start, double target_velocity,
                                const ProfileParameters& parameters);

/// Halt and quickstop: to rest with the given deceleration.
Trajectory plan_stop(const MotionState& start, double deceleration, RampShape shape);

} // namespace eposp::drives::motion
