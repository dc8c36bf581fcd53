#pragma once

#include <cstdint>
#include <optional>

namespace eposp::drives::escon2 {

/// ESCON2 FW spec table 59: the functionalities a digital input may carry (0x3142), by their
/// code; codes below 32 are also their bit in Digital inputs functionality 0x3143 (table 60).
enum class InputFunction : std::uint8_t {
    NegativeLimitSwitch = 0,
    PositiveLimitSwitch = 1,
    VelocitySetValueSwitch0 = 12,
    VelocitySetValueSwitch1 = 13,
    CurrentSetValueSwitch0 = 14,
    CurrentSetValueSwitch1 = 15,
    GeneralPurposeA = 16,
    GeneralPurposeB = 17,
    GeneralPurposeC = 18,
    GeneralPurposeD = 19,
    GeneralPurposeE = 20,
    GeneralPurposeF = 21,
    GeneralPurposeG = 22,
    GeneralPurposeH = 23,
    DriveEnable = 27,
    QuickStop = 28,
    Direction = 29,
    PwmVelocitySetValue = 32,
    PwmVelocitySetValueOffset = 33,
    PwmCurrentSetValue = 36,
    PwmCurrentSetValueOffset = 37,
    None = 255,
};

/// The functionality of a 0x3142 value, or none for a reserved code.
std::optional<InputFunction> input_function_from_code(std::uint8_t code);

/// Table 59 [a]: the PWM functionalities measure a signal and have no state bit.
bool is_pwm_function(InputFunction function);

/// Table 59 footnotes [b], [c]: the functionalities that act only in I/O Velocity Mode or only
/// in I/O Current Mode (the others act in both).
enum class IoMode { Velocity, Current };
bool acts_in(InputFunction function, IoMode mode);

/// The bit of `function` in 0x3143 (0 for PWM functionalities and None).
std::uint32_t function_bit(InputFunction function);

} // namespace eposp::drives::escon2
