#include "velocity_mode.hpp"

#include "analog_setpoint.hpp"

#include <algorithm>

namespace eposp::drives::epos2 {

void VelocityMode::start(double, std::int64_t, bool) {
    velocity_ = 0;
}

// The position demand is the actual position: a stop ramp of the device control starts from
// where the axis is, at the demanded velocity.
ModeDemand VelocityMode::demand(const ModeInputs& inputs) {
    const auto& od = services_.objects;
    const double set_value = executed_analog_setpoint(od, AnalogSetpoint::Velocity)
                                 .value_or(static_cast<double>(od.get_as<std::int32_t>(0x206B, 0)));
    const double max_velocity = services_.velocity_to_counts(od.get_as<std::uint32_t>(0x607F, 0));
    const double step = services_.rpm_to_counts(od.get_as<std::uint32_t>(0x60C5, 0)) *
                        plant::ServoAxis::kOuterLoopPeriod;
    const double target =
        std::clamp(services_.velocity_to_counts(set_value), -max_velocity, max_velocity);
    const double previous = velocity_;
    velocity_ = std::clamp(target, velocity_ - step, velocity_ + step);
    return {.motion = {static_cast<double>(inputs.position), velocity_,
                       (velocity_ - previous) / plant::ServoAxis::kOuterLoopPeriod},
            .loop = plant::ControlMode::Velocity};
}

} // namespace eposp::drives::epos2
