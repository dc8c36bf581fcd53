#include "eposp/drives/plant/reference_axis.hpp"

#include <numbers>

namespace eposp::drives::plant {

MotorParameters reference_dc_motor() {
    MotorParameters motor;
    motor.terminal_resistance = 2.18;
    motor.terminal_inductance = 0.238e-3;
    motor.torque_constant = 0.0234;
    motor.speed_constant = 60 / (2 * std::numbers::pi * 0.0234); // k_e = k_t in SI
    motor.rotor_inertia = 1.05e-6;
    return motor;
}

AxisParameters reference_axis() {
    AxisParameters axis;
    axis.plant.motor = reference_dc_motor();
    axis.plant.load = {5e-6, 1e-6, 1e-3};
    axis.encoder_pulses = 500;
    axis.gains.current = to_si(CurrentControlParameterSet{1190, 10900});
    axis.gains.velocity = to_si(VelocityControlParameterSet{487, 2290, 0, 259});
    axis.gains.position = to_si(PositionControlParameterSet{2285, 5000, 437, 0, 259});
    axis.gains.current_limit = 3;
    return axis;
}

} // namespace eposp::drives::plant
