#include "axis_configuration.hpp"

#include "eposp/canopen/entry_builder.hpp"
#include "velocity_units.hpp"

#include <algorithm>
#include <cmath>

namespace eposp::drives::epos2 {
namespace {

// Table 8-125: 1 brushed DC motor, 10 sinusoidal and 11 trapezoidal PM BL (EC) motor.
constexpr std::uint16_t kBrushedDcMotor = 1;
constexpr std::uint16_t kSinusoidalEcMotor = 10;
// Table 8-104, bit 0: "inverted Enc1 polarity".
constexpr std::uint16_t kEncoder1Inverted = 1U << 0;

} // namespace

void write_axis_defaults(canopen::ObjectDictionary& od, const plant::AxisParameters& machine) {
    canopen::set_default_as(od, 0x2210, 1, static_cast<std::uint32_t>(machine.encoder_pulses));
    // Table 8-104 bit 0: an encoder mounted the other way round is read inverted.
    canopen::set_default_as(
        od, 0x2210, 4,
        static_cast<std::uint16_t>(machine.encoder_mounting.counts_against_motor ? 1 : 0));
    const auto current = plant::to_parameter_set(machine.gains.current);
    canopen::set_default_as(od, 0x60F6, 1, current.p_gain);
    canopen::set_default_as(od, 0x60F6, 2, current.i_gain);
    const auto velocity = plant::to_parameter_set(machine.gains.velocity);
    canopen::set_default_as(od, 0x60F9, 1, velocity.p_gain);
    canopen::set_default_as(od, 0x60F9, 2, velocity.i_gain);
    canopen::set_default_as(od, 0x60F9, 4, velocity.velocity_feed_forward);
    canopen::set_default_as(od, 0x60F9, 5, velocity.acceleration_feed_forward);
    const auto position = plant::to_parameter_set(machine.gains.position);
    canopen::set_default_as(od, 0x60FB, 1, position.p_gain);
    canopen::set_default_as(od, 0x60FB, 2, position.i_gain);
    canopen::set_default_as(od, 0x60FB, 3, position.d_gain);
    canopen::set_default_as(od, 0x60FB, 4, position.velocity_feed_forward);
    canopen::set_default_as(od, 0x60FB, 5, position.acceleration_feed_forward);
    const plant::MotorParameters& motor = machine.plant.motor;
    canopen::set_default_as(
        od, 0x6402, 0, motor.kind == plant::MotorKind::Ec ? kSinusoidalEcMotor : kBrushedDcMotor);
    // 8.2.130: mA, at most the 10 A of an EPOS2 24/5.
    const double output_limit_ma =
        std::clamp(std::round(machine.gains.current_limit * 1000), 0.0, 10'000.0);
    canopen::set_default_as(od, 0x6410, 2, static_cast<std::uint16_t>(output_limit_ma));
    canopen::set_default_as(od, 0x6410, 3,
                            static_cast<std::uint8_t>(std::clamp(motor.pole_pairs, 1, 255)));
}

bool controller_gain_missing(const plant::ServoGains& gains, plant::ControlMode loop) {
    switch (loop) {
    case plant::ControlMode::PowerOff:
        return false;
    case plant::ControlMode::Current:
        return gains.current.kp == 0;
    case plant::ControlMode::Velocity:
        return gains.velocity.kp == 0 || gains.current.kp == 0;
    case plant::ControlMode::Position:
        return gains.position.kp == 0 || gains.current.kp == 0;
    }
    return false;
}

plant::AxisParameters configured_axis(const canopen::ObjectDictionary& od,
                                      plant::AxisParameters machine) {
    machine.encoder_pulses = static_cast<int>(od.get_as<std::uint32_t>(0x2210, 1));
    machine.encoder_reading = {.inverted =
                                   (od.get_as<std::uint16_t>(0x2210, 4) & kEncoder1Inverted) != 0,
                               .gear_ratio = motor_turns_per_sensor_turn(od)};
    machine.gains.current = plant::to_si(plant::CurrentControlParameterSet{
        od.get_as<std::int16_t>(0x60F6, 1), od.get_as<std::int16_t>(0x60F6, 2)});
    machine.gains.velocity = plant::to_si(plant::VelocityControlParameterSet{
        od.get_as<std::int16_t>(0x60F9, 1), od.get_as<std::int16_t>(0x60F9, 2),
        od.get_as<std::uint16_t>(0x60F9, 4), od.get_as<std::uint16_t>(0x60F9, 5)});
    machine.gains.position = plant::to_si(plant::PositionControlParameterSet{
        od.get_as<std::int16_t>(0x60FB, 1), od.get_as<std::int16_t>(0x60FB, 2),
        od.get_as<std::int16_t>(0x60FB, 3), od.get_as<std::uint16_t>(0x60FB, 4),
        od.get_as<std::uint16_t>(0x60FB, 5)});
    machine.gains.current_limit = od.get_as<std::uint16_t>(0x6410, 2) / 1000.0;
    plant::MotorParameters& motor = machine.plant.motor;
    motor.kind = od.get_as<std::uint16_t>(0x6402, 0) == kBrushedDcMotor
                     ? plant::MotorKind::BrushedDc
                     : plant::MotorKind::Ec;
    motor.pole_pairs = od.get_as<std::uint8_t>(0x6410, 3);
    return machine;
}

} // namespace eposp::drives::epos2
