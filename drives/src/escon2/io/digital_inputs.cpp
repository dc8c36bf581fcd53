#include "eposp/drives/escon2/io/digital_inputs.hpp"

#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

// 6.2.77, table 106: the CiA functionalities in 0x60FD.
constexpr std::uint32_t kCiaFunctions = 0x00FF'0003;

std::string function_name(InputFunction function) {
    return "functionality " + std::to_string(static_cast<unsigned>(function));
}

} // namespace

std::optional<std::string> configuration_error(const DigitalInputConfiguration& config) {
    for (unsigned n = 0; n < kDigitalInputCount; ++n) {
        const InputFunction function = config.functions[n];
        if (function == InputFunction::None) {
            continue;
        }
        if (is_pwm_function(function) && n >= 2) {
            return function_name(function) + " (PWM) is supported on digital input 1 and 2 " +
                   "only, not on input " + std::to_string(n + 1);
        }
        for (unsigned other = n + 1; other < kDigitalInputCount; ++other) {
            if (config.functions[other] == function) {
                return function_name(function) + " is mapped to input " + std::to_string(n + 1) +
                       " and input " + std::to_string(other + 1) +
                       "; each function can only be mapped once";
            }
        }
    }
    return std::nullopt;
}

DigitalInputs::DigitalInputs()
    : pins_{DebouncedInput(DebouncedInput::kRegularFilterTime),
            DebouncedInput(DebouncedInput::kRegularFilterTime),
            DebouncedInput(DebouncedInput::kRegularFilterTime),
            DebouncedInput(DebouncedInput::kRegularFilterTime),
            DebouncedInput(DebouncedInput::kHighSpeedFilterTime),
            DebouncedInput(DebouncedInput::kHighSpeedFilterTime),
            DebouncedInput(DebouncedInput::kHighSpeedFilterTime),
            DebouncedInput(DebouncedInput::kHighSpeedFilterTime)} {}

std::optional<std::string> DigitalInputs::configure(const DigitalInputConfiguration& config) {
    if (std::optional<std::string> error = configuration_error(config)) {
        return error;
    }
    config_ = config;
    return std::nullopt;
}

void DigitalInputs::set_level(unsigned input, bool high, double now) {
    if (input < 1 || input > kDigitalInputCount) {
        throw std::out_of_range("ESCON2 digital input " + std::to_string(input) +
                                " does not exist (1 - 4 regular, 5 - 8 high-speed)");
    }
    pins_[input - 1].set_level(high, now);
}

bool DigitalInputs::enabled(unsigned index) const {
    return !(config_.sensor2_configured && index + 1 >= kFirstHighSpeedInput);
}

std::uint16_t DigitalInputs::logic_state(double now) {
    std::uint16_t state = 0;
    for (unsigned n = 0; n < kDigitalInputCount; ++n) {
        const bool shown = enabled(n) && !is_pwm_function(config_.functions[n]);
        if (pins_[n].level(now) && shown) {
            state = static_cast<std::uint16_t>(state | (1U << n));
        }
    }
    return state;
}

// 6.2.26.2: polarity bit 0 is active high, 1 active low.
std::uint32_t DigitalInputs::functionality(double now) {
    std::uint32_t states = 0;
    for (unsigned n = 0; n < kDigitalInputCount; ++n) {
        const bool low_active = (config_.polarity & (1U << n)) != 0;
        if (enabled(n) && pins_[n].level(now) != low_active) {
            states |= function_bit(config_.functions[n]);
        }
    }
    return states;
}

std::uint32_t DigitalInputs::cia_inputs(double now) {
    return functionality(now) & kCiaFunctions;
}

bool DigitalInputs::active(InputFunction function, double now) {
    return (functionality(now) & function_bit(function)) != 0;
}

std::optional<unsigned> DigitalInputs::input_of(InputFunction function) const {
    for (unsigned n = 0; n < kDigitalInputCount; ++n) {
        if (enabled(n) && config_.functions[n] == function && function != InputFunction::None) {
            return n + 1;
        }
    }
    return std::nullopt;
}

std::optional<unsigned> DigitalInputs::selected_set_value(SetValueSwitch which, double now) {
    const bool velocity = which == SetValueSwitch::Velocity;
    const InputFunction switch0 =
        velocity ? InputFunction::VelocitySetValueSwitch0 : InputFunction::CurrentSetValueSwitch0;
    const InputFunction switch1 =
        velocity ? InputFunction::VelocitySetValueSwitch1 : InputFunction::CurrentSetValueSwitch1;
    if (!input_of(switch0) && !input_of(switch1)) {
        return std::nullopt;
    }
    return (active(switch1, now) ? 2U : 0U) + (active(switch0, now) ? 1U : 0U);
}

std::optional<DeviceErrorCode> DigitalInputs::limit_switch_error(double now) {
    if (active(InputFunction::NegativeLimitSwitch, now)) {
        return DeviceErrorCode::NegativeLimitSwitch;
    }
    if (active(InputFunction::PositiveLimitSwitch, now)) {
        return DeviceErrorCode::PositiveLimitSwitch;
    }
    return std::nullopt;
}

double apply_direction(double set_value, std::optional<bool> direction) {
    if (!direction) {
        return set_value;
    }
    if (set_value < 0) {
        return 0;
    }
    return *direction ? set_value : -set_value;
}

} // namespace eposp::drives::escon2
