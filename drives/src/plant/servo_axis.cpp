#include "eposp/drives/plant/servo_axis.hpp"

#include <algorithm>
#include <limits>
#include <numbers>

namespace eposp::drives::plant {

namespace {

// Motor-shaft radians per count as the firmware reads its encoder: through the gear it believes
// in (the gains are motor-shaft quantities, 8.2.74: the encoder is on the gear's output side).
double radians_per_count(const AxisParameters& parameters) {
    return 2 * std::numbers::pi / static_cast<double>(counts_per_turn(parameters.encoder_pulses)) *
           parameters.encoder_reading.gear_ratio;
}

// The mounting's direction and the reading's: an encoder mounted the other way round reads
// right when the firmware inverts it.
double encoder_sign(const AxisParameters& parameters) {
    return parameters.encoder_mounting.counts_against_motor == parameters.encoder_reading.inverted
               ? 1.0
               : -1.0;
}

// The counts one motor-shaft radian moves the reading by: scales the velocity measurement
// across a reconfiguration.
double counts_per_motor_radian(const AxisParameters& parameters) {
    const double ratio =
        parameters.encoder_mounting.on_gear_output ? parameters.plant.gearhead.ratio : 1.0;
    return encoder_sign(parameters) *
           static_cast<double>(counts_per_turn(parameters.encoder_pulses)) / ratio;
}

PidController::Gains current_law(const ServoGains& gains) {
    return {gains.current.kp, gains.current.ki, 0};
}
PidController::Gains velocity_law(const ServoGains& gains) {
    return {gains.velocity.kp, gains.velocity.ki, 0};
}
PidController::Gains position_law(const ServoGains& gains) {
    return {gains.position.kp, gains.position.ki, gains.position.kd};
}

} // namespace

ServoAxis::ServoAxis(const AxisParameters& parameters)
    : parameters_(parameters), motor_(parameters.plant, kCurrentLoopPeriod),
      radians_per_count_(radians_per_count(parameters)), encoder_sign_(encoder_sign(parameters)),
      current_controller_(current_law(parameters.gains),
                          parameters.plant.power_stage.max_voltage()),
      velocity_controller_(velocity_law(parameters.gains), parameters.gains.current_limit),
      position_controller_(position_law(parameters.gains), parameters.gains.current_limit),
      current_limit_(parameters.gains.current_limit),
      revolution_(revolution_of(position_, parameters.encoder_pulses)) {}

void ServoAxis::reconfigure(const AxisParameters& parameters) {
    const MotorState state = motor_.state();
    const double scale = counts_per_motor_radian(parameters) / counts_per_motor_radian(parameters_);
    parameters_ = parameters;
    switches_angle_ = std::numeric_limits<double>::quiet_NaN();
    motor_ = MotorModel(parameters.plant, kCurrentLoopPeriod);
    motor_.set_state(state);
    radians_per_count_ = radians_per_count(parameters);
    encoder_sign_ = encoder_sign(parameters);
    current_controller_.retune(current_law(parameters.gains),
                               parameters.plant.power_stage.max_voltage());
    velocity_controller_.retune(velocity_law(parameters.gains), parameters.gains.current_limit);
    position_controller_.retune(position_law(parameters.gains), parameters.gains.current_limit);
    apply_current_limit();
    // The velocity measured at the next outer loop stays in step with the new resolution.
    const std::int64_t position = quadcounts(encoder_angle(), parameters.encoder_pulses);
    position_at_outer_loop_ =
        position -
        static_cast<std::int64_t>(static_cast<double>(position_ - position_at_outer_loop_) * scale);
    position_ = position;
    revolution_ = revolution_of(position_, parameters.encoder_pulses);
}

void ServoAxis::reduce_current_limit(double amperes) {
    if (amperes != reduced_current_limit_) {
        reduced_current_limit_ = amperes;
        apply_current_limit();
    }
}

// The outer loops' output limit, and their anti-windup with it, follow the limit in force.
void ServoAxis::apply_current_limit() {
    const double configured = parameters_.gains.current_limit;
    current_limit_ =
        reduced_current_limit_ > 0 ? std::min(configured, reduced_current_limit_) : configured;
    velocity_controller_.retune(velocity_law(parameters_.gains), current_limit_);
    position_controller_.retune(position_law(parameters_.gains), current_limit_);
}

void ServoAxis::set_mode(ControlMode mode) {
    if (mode != mode_) {
        mode_ = mode;
        reset_controllers();
    }
}

void ServoAxis::reset_controllers() {
    current_controller_.reset();
    velocity_controller_.reset();
    position_controller_.reset();
    current_demand_ = 0;
    speed_limiting_ = false;
    // The outer loop keeps its 1 ms rhythm, so the velocity measurement keeps its interval.
}

void ServoAxis::run_outer_loop() {
    velocity_ = static_cast<double>(position_ - position_at_outer_loop_) / kOuterLoopPeriod;
    position_at_outer_loop_ = position_;
    // Demands in quadcounts become motor-shaft radians, the unit of the gains.
    const double velocity_demand = demand_.velocity * radians_per_count_;
    const double acceleration_demand = demand_.acceleration * radians_per_count_;
    switch (mode_) {
    case ControlMode::PowerOff:
        current_demand_ = 0;
        break;
    case ControlMode::Current:
        current_demand_ = std::clamp(demand_.current, -current_limit_, current_limit_);
        if (demand_.speed_limit > 0) {
            current_demand_ = cap_at_speed_limit(current_demand_);
        }
        break;
    case ControlMode::Velocity: {
        const VelocityGains& gains = parameters_.gains.velocity;
        const double feed_forward = gains.velocity_feed_forward * velocity_demand +
                                    gains.acceleration_feed_forward * acceleration_demand;
        current_demand_ = velocity_controller_.update(
            velocity_demand - velocity_ * radians_per_count_, kOuterLoopPeriod, feed_forward);
        break;
    }
    case ControlMode::Position: {
        const PositionGains& gains = parameters_.gains.position;
        const double feed_forward = gains.velocity_feed_forward * velocity_demand +
                                    gains.acceleration_feed_forward * acceleration_demand;
        const double error =
            (demand_.position - static_cast<double>(position_)) * radians_per_count_;
        current_demand_ = position_controller_.update(error, kOuterLoopPeriod, feed_forward);
        break;
    }
    }
}

// 8.2.130 sub 4: once the speed reaches the limit in the direction of the current, the velocity
// controller takes over from the set value without a bump and holds the limit; it hands back
// when it would demand more than the set value.
double ServoAxis::cap_at_speed_limit(double current) {
    const double limit = current >= 0 ? demand_.speed_limit : -demand_.speed_limit;
    if (!speed_limiting_) {
        const bool reached = current >= 0 ? velocity_ >= limit : velocity_ <= limit;
        if (!reached) {
            return current;
        }
        velocity_controller_.preset(current);
        speed_limiting_ = true;
    }
    const double cap =
        velocity_controller_.update((limit - velocity_) * radians_per_count_, kOuterLoopPeriod);
    if (current >= 0 ? cap >= current : cap <= current) {
        speed_limiting_ = false;
        return current;
    }
    return cap;
}

std::uint8_t ServoAxis::hall_sensors() const {
    const MotorParameters& motor = parameters_.plant.motor;
    return motor.kind == MotorKind::Ec ? hall_pattern(motor_.state().angle, motor.pole_pairs) : 0;
}

} // namespace eposp::drives::plant
