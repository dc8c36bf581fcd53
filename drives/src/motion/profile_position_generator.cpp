#include "eposp/drives/motion/profile_position_generator.hpp"

namespace eposp::drives::motion {

ProfilePositionGenerator::ProfilePositionGenerator(double position) {
    reset(position);
}

void ProfilePositionGenerator::reset(double position) {
    trajectory_ = Trajectory(position, {});
    start_time_ = 0;
    buffered_.reset();
    active_.reset();
    halted_ = false;
}

bool ProfilePositionGenerator::new_setpoint(double now, const PositionSetpoint& setpoint,
                                            bool change_immediately) {
    if (change_immediately) {
        buffered_.reset();
        start(now, update(now), setpoint);
        return true;
    }
    if (buffered_) {
        return false;
    }
    if (finished(now)) {
        start(now, update(now), setpoint);
    } else {
        buffered_ = setpoint;
    }
    return true;
}

// 5.3.2.3: relative targets add to the position demand value where the move starts, so a
// buffered relative setpoint counts from the previous target.
void ProfilePositionGenerator::start(double now, const MotionState& from,
                                     const PositionSetpoint& setpoint) {
    PositionSetpoint absolute = setpoint;
    if (setpoint.relative) {
        absolute.target += from.position;
        absolute.relative = false;
    }
    active_ = absolute;
    start_time_ = now;
    const ProfileParameters& parameters = absolute.parameters;
    if (halted_) {
        trajectory_ = plan_stop(from, parameters.deceleration, parameters.shape);
    } else if (absolute.endless) {
        trajectory_ = plan_velocity_change(
            from, setpoint.target < 0 ? -parameters.velocity : parameters.velocity, parameters);
    } else {
        trajectory_ = plan_position_move(from, absolute.target, parameters);
    }
}

void ProfilePositionGenerator::set_halt(double now, bool halt) {
    if (halt == halted_) {
        return;
    }
    halted_ = halt;
    if (active_) {
        start(now, update(now), *active_);
    }
}

void ProfilePositionGenerator::quick_stop(double now, double deceleration, RampShape shape) {
    const MotionState from = update(now);
    buffered_.reset();
    active_.reset();
    start_time_ = now;
    trajectory_ = plan_stop(from, deceleration, shape);
}

MotionState ProfilePositionGenerator::update(double now) {
    const double end = start_time_ + trajectory_.duration();
    if (buffered_ && !halted_ && at_rest(now)) {
        // The next move starts exactly when the last one ended, at rest on its target.
        const PositionSetpoint next = *buffered_;
        buffered_.reset();
        start(end, trajectory_.sample(trajectory_.duration()), next);
    }
    return trajectory_.sample(now - start_time_);
}

bool ProfilePositionGenerator::finished(double now) const {
    return !buffered_ && at_rest(now);
}

bool ProfilePositionGenerator::at_rest(double now) const {
    return now >= start_time_ + trajectory_.duration() && trajectory_.final_velocity() == 0;
}

} // namespace eposp::drives::motion
