#include "eposp/drives/escon2/io/analog_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

// The set values an input functionality drives (table 59 [e], table 68 [a]).
enum class Target { None, Velocity, VelocityOffset, Current, CurrentOffset };

Target target_of(AnalogInputFunction function) {
    switch (function) {
    case AnalogInputFunction::VelocitySetValue:
        return Target::Velocity;
    case AnalogInputFunction::VelocitySetValueOffset:
        return Target::VelocityOffset;
    case AnalogInputFunction::CurrentSetValue:
        return Target::Current;
    case AnalogInputFunction::CurrentSetValueOffset:
        return Target::CurrentOffset;
    default:
        return Target::None;
    }
}

Target target_of(InputFunction function) {
    switch (function) {
    case InputFunction::PwmVelocitySetValue:
    case InputFunction::VelocitySetValueSwitch0:
    case InputFunction::VelocitySetValueSwitch1:
        return Target::Velocity;
    case InputFunction::PwmVelocitySetValueOffset:
        return Target::VelocityOffset;
    case InputFunction::PwmCurrentSetValue:
    case InputFunction::CurrentSetValueSwitch0:
    case InputFunction::CurrentSetValueSwitch1:
        return Target::Current;
    case InputFunction::PwmCurrentSetValueOffset:
        return Target::CurrentOffset;
    default:
        return Target::None;
    }
}

} // namespace

std::optional<AnalogInputFunction> analog_input_function_from_code(std::uint8_t code) {
    if (code <= 1 || (code >= 8 && code <= 11) || code == 255) {
        return static_cast<AnalogInputFunction>(code);
    }
    return std::nullopt;
}

std::optional<std::string> configuration_error(const AnalogInputConfiguration& analog,
                                               const DigitalInputConfiguration& digital) {
    const AnalogInputFunction first = analog.functions[0];
    if (first != AnalogInputFunction::None && first == analog.functions[1]) {
        return "analog functionality " + std::to_string(static_cast<unsigned>(first)) +
               " is mapped to both analog inputs; each function can only be mapped once";
    }
    for (unsigned a = 0; a < kAnalogInputCount; ++a) {
        const Target target = target_of(analog.functions[a]);
        if (target == Target::None) {
            continue;
        }
        for (unsigned d = 0; d < kDigitalInputCount; ++d) {
            if (target_of(digital.functions[d]) == target) {
                return "analog input " + std::to_string(a + 1) + " and digital input " +
                       std::to_string(d + 1) +
                       " both set the same target; only one input functionality (analog or " +
                       "digital) can be active per target";
            }
        }
    }
    return std::nullopt;
}

AnalogInputs::AnalogInputs(double low, double high) : low_(low), high_(high) {
    if (!(high > low)) {
        throw std::invalid_argument("an analog input range needs high > low");
    }
}

std::optional<std::string> AnalogInputs::configure(const AnalogInputConfiguration& config,
                                                   const DigitalInputConfiguration& digital) {
    if (std::optional<std::string> error = configuration_error(config, digital)) {
        return error;
    }
    config_ = config;
    return std::nullopt;
}

unsigned AnalogInputs::checked(unsigned input) const {
    if (input < 1 || input > kAnalogInputCount) {
        throw std::out_of_range("ESCON2 analog input " + std::to_string(input) +
                                " does not exist (1 or 2)");
    }
    return input - 1;
}

void AnalogInputs::set_voltage(unsigned input, double volts) {
    pins_[checked(input)] = std::clamp(volts, low_, high_);
}

double AnalogInputs::voltage(unsigned input) const {
    const unsigned n = checked(input);
    const AnalogInputAdjustment& adjustment = config_.adjustments[n];
    return (pins_[n] + adjustment.offset) * adjustment.gain; // 6.2.39: offset before gain
}

std::uint16_t AnalogInputs::raw_value(unsigned input) const {
    constexpr double kFullScale = (1U << kAdcBits) - 1;
    return static_cast<std::uint16_t>(
        std::lround((pins_[checked(input)] - low_) / (high_ - low_) * kFullScale));
}

std::optional<double> AnalogInputs::voltage_for(AnalogInputFunction function) const {
    for (unsigned n = 0; n < kAnalogInputCount; ++n) {
        if (function != AnalogInputFunction::None && config_.functions[n] == function) {
            return voltage(n + 1);
        }
    }
    return std::nullopt;
}

double AnalogInputs::general_purpose(AnalogInputFunction which) const {
    return voltage_for(which).value_or(0);
}

} // namespace eposp::drives::escon2
