#include "eposp/drives/escon2/device_errors.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

using enum FaultReactionCode;
using enum ErrorRecovery;

// ESCON2 FW spec table 110, row by row (code, error register, name, fault reaction code), with
// the recovery of its section 7.1.x.
constexpr auto kDeviceErrors = std::to_array<DeviceError>({
    {0x1000, 0b0000'0001, "Generic error", Disable, FaultReset},
    {0x1080, 0b0000'0001, "Generic initialisation error", Disable, ResetDevice},
    {0x2310, 0b0000'0011, "Overcurrent error", Disable, FaultReset},
    {0x2320, 0b0000'0011, "Power stage protection error", Disable, FaultReset},
    {0x2380, 0b0000'0011, "Power stage protection error", Disable, FaultReset},
    {0x3210, 0b0000'0101, "Overvoltage error", Disable, FaultReset},
    {0x3220, 0b0000'0101, "Undervoltage error", Disable, FaultReset},
    {0x4382, 0b0000'1001, "Thermal power stage overload error", Disable, FaultReset},
    {0x4383, 0b0000'1001, "Thermal power stage overload warning", Warning, AutoClear},
    {0x4384, 0b0000'1001, "Thermal logic section overload error", Disable, FaultReset},
    {0x5480, 0b0000'0001, "Hardware error", Disable, ResetDevice},
    {0x5481, 0b0000'0001, "Hardware defect loading parameter error", Disable, ResetDevice},
    {0x5482, 0b0000'0001, "Hardware configuration error", Disable, ResetDevice},
    {0x5483, 0b0000'0001, "Hardware configuration error", Disable, ResetDevice},
    {0x6180, 0b0000'0001, "Internal software error", Disable, ResetDevice},
    {0x6181, 0b0000'0001, "Internal software error", Disable, FaultReset},
    {0x6380, 0b0000'0001, "Loading parameter failed error", Disable, FaultReset},
    {0x6381, 0b0000'0001, "Loading parameter failed error", Disable, ResetDevice},
    {0x6382, 0b0000'0001, "Loading parameter failed error", Disable, ResetDevice},
    {0x6388, 0b0000'0001, "Torque constant parameter error", Disable, FaultReset},
    {0x7280, 0b0000'0001, "Current offset adjustment warning", Warning, AutoClear},
    {0x7380, 0b0010'0001, "Main sensor breach error", Disable, FaultReset},
    {0x7388, 0b0010'0001, "Hall sensor signal error", Disable, FaultReset},
    {0x738A, 0b0010'0001, "Hall angle detection error", Disable, FaultReset},
    {0x7390, 0b0010'0001, "Missing main sensor error", Disable, FaultReset},
    {0x7391, 0b0010'0001, "Missing commutation sensor error", Disable, FaultReset},
    {0x7392, 0b0010'0001, "Main sensor direction error", Disable, FaultReset},
    {0x8A80, 0b0010'0001, "Negative limit switch error", QuickStop, FaultReset},
    {0x8A81, 0b0010'0001, "Positive limit switch error", QuickStop, FaultReset},
    {0x8A89, 0b0000'0001, "Digital input 1 PWM frequency warning", Warning, AutoClear},
    {0x8A8A, 0b0000'0001, "Digital input 1 PWM duty cycle warning", Warning, AutoClear},
    {0x8A8C, 0b0000'0001, "Digital input 1 PWM error", Disable, FaultReset},
    {0x8A8D, 0b0000'0001, "Digital input 2 PWM frequency warning", Warning, AutoClear},
    {0x8A8E, 0b0000'0001, "Digital input 2 PWM duty cycle warning", Warning, AutoClear},
    {0x8A90, 0b0000'0001, "Digital input 2 PWM error", Disable, FaultReset},
    {0xFF01, 0b0000'0001, "System overloaded warning", Warning, ClearWarning},
    {0xFF02, 0b0000'0001, "Watchdog error", Disable, FaultReset},
    {0xFF03, 0b0000'0001, "Watchdog error", Disable, FaultReset},
    {0xFF06, 0b0000'0001, "System peak overloaded error", Disable, FaultReset},
    {0xFF07, 0b0000'0001, "System peak overloaded error", Disable, FaultReset},
    {0xFF0D, 0b0000'0001, "Mode of operation not supported error", Disable, FaultReset},
    {0xFF11, 0b0010'0001, "Regulation tuning identification error", Disable, FaultReset},
    {0xFF12, 0b0010'0001, "Regulation tuning current error", Disable, FaultReset},
    {0xFF13, 0b0010'0001, "Regulation tuning identification current error", Disable, FaultReset},
    {0xFF14, 0b0010'0001, "Regulation tuning unrealistic result error", Disable, FaultReset},
    {0xFF15, 0b0010'0001, "Regulation tuning identification error", Disable, FaultReset},
    {0xFF16, 0b0010'0001, "Regulation tuning identification error", Disable, FaultReset},
    {0xFF17, 0b0010'0001, "Regulation tuning identification error", Disable, FaultReset},
    {0xFF19, 0b0010'0001, "Regulation tuning identification error", Disable, FaultReset},
    {0xFF20, 0b0010'0001, "Regulation tuning standstill error", Disable, FaultReset},
    {0xFF21, 0b0010'0001, "Regulation tuning torque constant error", Disable, FaultReset},
    {0xFF22, 0b0010'0001, "Regulation tuning max system speed error", Disable, FaultReset},
    {0xFF23, 0b0010'0001, "Regulation tuning motor connection error", Disable, FaultReset},
    {0xFF24, 0b0010'0001, "Regulation tuning sensor signal error", Disable, FaultReset},
});

} // namespace

std::span<const DeviceError> device_errors() {
    return kDeviceErrors;
}

const DeviceError& device_error(std::uint16_t code) {
    const auto* row = std::ranges::find(kDeviceErrors, code, &DeviceError::code);
    if (row == kDeviceErrors.end()) {
        throw std::invalid_argument(
            fmt::format("0x{:04X} is not an error of ESCON2 FW spec table 110", code));
    }
    return *row;
}

} // namespace eposp::drives::escon2
