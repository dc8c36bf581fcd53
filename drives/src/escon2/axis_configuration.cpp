#include "axis_configuration.hpp"

#include "eposp/canopen/entry_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eposp::drives::escon2 {
namespace {

constexpr std::uint16_t kBrushedDcMotor = 1;        // table 108
constexpr std::uint16_t kSinusoidalEcMotor = 10;    // table 108
constexpr std::uint16_t kEncoderInverted = 1U << 4; // table 55: 0x3010 sub 2 "Direction"
constexpr double kMicro = 1e-6;
constexpr double kMicroPerMilli = 1e-3; // µV/(A·ms) in V/(A·s)

std::uint32_t in_units(double si, double unit) {
    return static_cast<std::uint32_t>(
        std::clamp(std::round(si / unit), 0.0, double{std::numeric_limits<std::uint32_t>::max()}));
}

double gain(const canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub,
            double unit) {
    return od.get_as<std::uint32_t>(index, sub) * unit;
}

} // namespace

void write_axis_defaults(canopen::ObjectDictionary& od, const plant::AxisParameters& machine) {
    canopen::set_default_as(od, 0x3010, 1, static_cast<std::uint32_t>(machine.encoder_pulses));
    const plant::ServoGains& gains = machine.gains;
    canopen::set_default_as(od, 0x30A0, 1, in_units(gains.current.kp, kMicro));
    canopen::set_default_as(od, 0x30A0, 2, in_units(gains.current.ki, kMicroPerMilli));
    canopen::set_default_as(od, 0x30A2, 1, in_units(gains.velocity.kp, kMicro));
    canopen::set_default_as(od, 0x30A2, 2, in_units(gains.velocity.ki, kMicro));
    canopen::set_default_as(od, 0x30A2, 3, in_units(gains.velocity.velocity_feed_forward, kMicro));
    canopen::set_default_as(od, 0x30A2, 4,
                            in_units(gains.velocity.acceleration_feed_forward, kMicro));
    const auto& limit = od.find(0x3001, 2);
    const double max_ma = static_cast<double>(canopen::decode<std::uint32_t>(*limit->high_limit));
    canopen::set_default_as(od, 0x3001, 2,
                            static_cast<std::uint32_t>(
                                std::clamp(std::round(gains.current_limit * 1000), 0.0, max_ma)));
    const plant::MotorParameters& motor = machine.plant.motor;
    canopen::set_default_as(od, 0x3001, 3,
                            static_cast<std::uint8_t>(std::clamp(motor.pole_pairs, 1, 255)));
    const bool brushed = motor.kind == plant::MotorKind::BrushedDc;
    canopen::set_default_as(od, 0x6402, 0, brushed ? kBrushedDcMotor : kSinusoidalEcMotor);
    if (brushed) {
        canopen::set_default_as(od, 0x3000, 1, std::uint32_t{0x100}); // the encoder alone
        canopen::set_default_as(od, 0x3000, 3, std::uint32_t{0});
    }
}

plant::AxisParameters configured_axis(const canopen::ObjectDictionary& od,
                                      plant::AxisParameters machine) {
    machine.encoder_pulses = static_cast<int>(od.get_as<std::uint32_t>(0x3010, 1));
    machine.encoder_reading.inverted =
        (od.get_as<std::uint16_t>(0x3010, 2) & kEncoderInverted) != 0;
    plant::ServoGains& gains = machine.gains;
    gains.current = {gain(od, 0x30A0, 1, kMicro), gain(od, 0x30A0, 2, kMicroPerMilli)};
    gains.velocity = {gain(od, 0x30A2, 1, kMicro), gain(od, 0x30A2, 2, kMicro),
                      gain(od, 0x30A2, 3, kMicro), gain(od, 0x30A2, 4, kMicro)};
    gains.current_limit = od.get_as<std::uint32_t>(0x3001, 2) / 1000.0;
    plant::MotorParameters& motor = machine.plant.motor;
    motor.kind = od.get_as<std::uint16_t>(0x6402, 0) == kBrushedDcMotor
                     ? plant::MotorKind::BrushedDc
                     : plant::MotorKind::Ec;
    motor.pole_pairs = od.get_as<std::uint8_t>(0x3001, 3);
    return machine;
}

} // namespace eposp::drives::escon2
