#include "current_mode.hpp"

#include "../velocity_units.hpp"
#include "analog_setpoint.hpp"

#include <algorithm>

namespace eposp::drives::epos2 {

// The motion is the actual one: a stop ramp of the device control starts from it.
ModeDemand CurrentMode::demand(const ModeInputs& inputs) {
    const auto& od = services_.objects;
    const double set_value = executed_analog_setpoint(od, AnalogSetpoint::Current)
                                 .value_or(static_cast<double>(od.get_as<std::int16_t>(0x2030, 0)));
    const double limit = od.get_as<std::uint16_t>(0x6410, 2);
    return {.motion = {static_cast<double>(inputs.position), inputs.velocity, 0},
            .loop = plant::ControlMode::Current,
            .current = std::clamp(set_value, -limit, limit) / 1000.0,
            // 8.2.130: the motor's speed; the encoder turns 1 / gear ratio as fast (8.2.74).
            .speed_limit = services_.rpm_to_counts(od.get_as<std::uint32_t>(0x6410, 4) /
                                                   motor_turns_per_sensor_turn(od))};
}

} // namespace eposp::drives::epos2
