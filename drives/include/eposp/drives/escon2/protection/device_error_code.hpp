#pragma once

#include <cstdint>

namespace eposp::drives::escon2 {

/// The device errors of ESCON2 FW spec table 110 (7.1) that the I/O and protection classes
/// raise; the drive enters them with their error register bits and reaction.
enum class DeviceErrorCode : std::uint16_t {
    Overvoltage = 0x3210,
    Undervoltage = 0x3220,
    ThermalPowerStageOverload = 0x4382,
    ThermalPowerStageOverloadWarning = 0x4383,
    ThermalLogicSectionOverload = 0x4384,
    NegativeLimitSwitch = 0x8A80,
    PositiveLimitSwitch = 0x8A81,
    DigitalInput1PwmFrequencyWarning = 0x8A89,
    DigitalInput1PwmDutyCycleWarning = 0x8A8A,
    DigitalInput1PwmError = 0x8A8C,
    DigitalInput2PwmFrequencyWarning = 0x8A8D,
    DigitalInput2PwmDutyCycleWarning = 0x8A8E,
    DigitalInput2PwmError = 0x8A90,
    SystemOverloadedWarning = 0xFF01,
    Watchdog = 0xFF02,
    SystemPeakOverloaded = 0xFF06,
};

} // namespace eposp::drives::escon2
