#include "eposp/drives/escon2/io/input_function.hpp"

namespace eposp::drives::escon2 {

std::optional<InputFunction> input_function_from_code(std::uint8_t code) {
    const bool defined = code <= 1 || (code >= 12 && code <= 23) || (code >= 27 && code <= 29) ||
                         code == 32 || code == 33 || code == 36 || code == 37 || code == 255;
    if (!defined) {
        return std::nullopt;
    }
    return static_cast<InputFunction>(code);
}

bool is_pwm_function(InputFunction function) {
    return function != InputFunction::None && static_cast<std::uint8_t>(function) >= 32;
}

bool acts_in(InputFunction function, IoMode mode) {
    switch (function) {
    case InputFunction::PwmVelocitySetValue:
    case InputFunction::PwmVelocitySetValueOffset:
    case InputFunction::VelocitySetValueSwitch0:
    case InputFunction::VelocitySetValueSwitch1:
        return mode == IoMode::Velocity; // [b]
    case InputFunction::PwmCurrentSetValue:
    case InputFunction::PwmCurrentSetValueOffset:
    case InputFunction::CurrentSetValueSwitch0:
    case InputFunction::CurrentSetValueSwitch1:
        return mode == IoMode::Current; // [c]
    default:
        return true; // Direction is [b][c]: both I/O modes
    }
}

std::uint32_t function_bit(InputFunction function) {
    const auto code = static_cast<unsigned>(function);
    return code < 32 ? 1U << code : 0;
}

} // namespace eposp::drives::escon2
