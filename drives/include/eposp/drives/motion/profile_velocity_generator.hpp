#pragma once

#include "eposp/drives/motion/profile_planner.hpp"

namespace eposp::drives::motion {

/// The Profile Velocity trajectory generator (EPOS2 FW spec 5.10.1): every new target velocity
/// (0x60FF) is ramped to from the present demand, halt (controlword bit 8) ramps to zero with
/// the profile deceleration and its release ramps back to the target, quickstop ramps to zero
/// with the quickstop deceleration. Times are seconds on the caller's clock.
class ProfileVelocityGenerator {
public:
    explicit ProfileVelocityGenerator(double position = 0);

    void set_target(double now, double target_velocity, const ProfileParameters& parameters);
    void set_halt(double now, bool halt);
    void quick_stop(double now, double deceleration);
    /// Start over at rest at `position`.
    void reset(double position);

    MotionState update(double now) const;
    /// The demand has reached its final velocity (the target, or zero when halted/stopped).
    bool ramp_finished(double now) const;

private:
    void replan(double now);

    Trajectory trajectory_;
    double start_time_ = 0;
    double target_ = 0;
    ProfileParameters parameters_;
    bool halted_ = false;
};

} // namespace eposp::drives::motion
