#include "analog_setpoint.hpp"

#include "eposp/canopen/entry_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eposp::drives::epos2 {
namespace {

constexpr std::uint16_t kConfigurationObject = 0x2301; ///< + the functionality's code

std::uint16_t configuration_of(AnalogSetpoint which) {
    return static_cast<std::uint16_t>(kConfigurationObject + static_cast<std::uint16_t>(which));
}

// Table 8-97: the analog input (1, 2) assigned `which`, if any.
std::optional<std::uint8_t> assigned_input(const canopen::ObjectDictionary& od,
                                           AnalogSetpoint which) {
    for (std::uint8_t input = 1; input <= 2; ++input) {
        if (od.get_as<std::uint16_t>(0x207B, input) == static_cast<std::uint16_t>(which)) {
            return input;
        }
    }
    return std::nullopt;
}

template <typename T>
T rounded_to(double value) {
    using Limits = std::numeric_limits<T>;
    return static_cast<T>(std::clamp<double>(std::round(value), Limits::min(), Limits::max()));
}

} // namespace

// Tables 8-109 - 8-111 give the notation index as the factor 10^index on the scaling per volt;
// 0x207C holds millivolts (8.2.63).
double analog_setpoint(const canopen::ObjectDictionary& od, AnalogSetpoint which) {
    const std::uint16_t index = configuration_of(which);
    const std::optional<std::uint8_t> input = assigned_input(od, which);
    const double volts = input ? od.get_as<std::int16_t>(0x207C, *input) / 1000.0 : 0.0;
    const double scaling =
        od.get_as<std::int16_t>(index, 1) * std::pow(10.0, od.get_as<std::int8_t>(index, 3));
    const double offset = which == AnalogSetpoint::Current ? od.get_as<std::int16_t>(index, 2)
                                                           : od.get_as<std::int32_t>(index, 2);
    return volts * scaling + offset;
}

std::optional<double> executed_analog_setpoint(const canopen::ObjectDictionary& od,
                                               AnalogSetpoint which) {
    const auto bit = static_cast<std::uint16_t>(1U << static_cast<std::uint16_t>(which));
    if ((od.get_as<std::uint16_t>(0x207D, 0) & bit) == 0 || !assigned_input(od, which)) {
        return std::nullopt;
    }
    return analog_setpoint(od, which);
}

void compute_analog_setpoints(canopen::ObjectDictionary& od) {
    const auto computed = [&od](AnalogSetpoint which, auto convert) {
        od.find(configuration_of(which), 4)->on_read = [&od, which, convert] {
            return canopen::encode(convert(analog_setpoint(od, which)));
        };
    };
    computed(AnalogSetpoint::Current, rounded_to<std::int16_t>);
    computed(AnalogSetpoint::Velocity, rounded_to<std::int32_t>);
    computed(AnalogSetpoint::Position, rounded_to<std::int32_t>);
}

// 8.2.62: "A functionality can only be assigned to one of the two analog inputs at the same time."
void guard_analog_input_assignment(canopen::ObjectDictionary& od) {
    for (std::uint8_t input = 1; input <= 2; ++input) {
        const auto other = static_cast<std::uint8_t>(3 - input);
        canopen::Entry(*od.find(0x207B, input))
            .rule([&od, other](std::span<const std::uint8_t> value) {
                return canopen::decode<std::uint16_t>(value) ==
                               od.get_as<std::uint16_t>(0x207B, other)
                           ? canopen::AbortCode::ParameterIncompatibility
                           : canopen::AbortCode::None;
            });
    }
}

} // namespace eposp::drives::epos2
