#pragma once

#include "eposp/drives/motion/velocity_ramp.hpp"

namespace eposp::drives::motion {

/// Position Mode (EPOS2 FW spec 5.6): the position demand is the set value, which the master
/// generates ("there is no trajectory generator"), within Maximal Profile Velocity 0x607F and Max
/// Acceleration 0x60C5 (table 5-37). A set value that moves within them is followed exactly; a
/// jump is approached at most at the maximal velocity and acceleration and stopped on without
/// overshoot. Discrete: one update per control period.
class PositionSetValueLimiter {
public:
    /// At rest at `position`.
    explicit PositionSetValueLimiter(double position = 0);

    /// The demand one period `dt` later for `set_value`; the velocity of the set value is taken
    /// from its change since the last update.
    MotionState update(double set_value, double max_velocity, double max_acceleration, double dt);

private:
    MotionState demand_;
    double last_set_value_;
};

} // namespace eposp::drives::motion
