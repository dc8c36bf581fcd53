#include "eposp/drives/motion/profile_velocity_generator.hpp"

namespace eposp::drives::motion {

ProfileVelocityGenerator::ProfileVelocityGenerator(double position) {
    reset(position);
}

void ProfileVelocityGenerator::reset(double position) {
    trajectory_ = Trajectory(position, {});
    start_time_ = 0;
    target_ = 0;
    halted_ = false;
}

void ProfileVelocityGenerator::set_target(double now, double target_velocity,
                                          const ProfileParameters& parameters) {
    target_ = target_velocity;
    parameters_ = parameters;
    replan(now);
}

void ProfileVelocityGenerator::set_halt(double now, bool halt) {
    if (halt != halted_) {
        halted_ = halt;
        replan(now);
    }
}

void ProfileVelocityGenerator::quick_stop(double now, double deceleration) {
    const MotionState from = update(now);
    target_ = 0;
    start_time_ = now;
    trajectory_ = plan_stop(from, deceleration, parameters_.shape);
}

void ProfileVelocityGenerator::replan(double now) {
    const MotionState from = update(now);
    start_time_ = now;
    // Halt decelerates with the profile deceleration (table 5-51), like a target of zero.
    trajectory_ = plan_velocity_change(from, halted_ ? 0.0 : target_, parameters_);
}

MotionState ProfileVelocityGenerator::update(double now) const {
    return trajectory_.sample(now - start_time_);
}

bool ProfileVelocityGenerator::ramp_finished(double now) const {
    return now >= start_time_ + trajectory_.duration();
}

} // namespace eposp::drives::motion
