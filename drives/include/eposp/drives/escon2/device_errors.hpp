#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace eposp::drives::escon2 {

/// ESCON2 FW spec 7.1: the fault reaction codes of table 110.
enum class FaultReactionCode : char {
    QuickStop = 'f', ///< decelerate with the quick stop ramp, then disable the drive function
    Disable = 'd',   ///< a secure movement is no longer possible: disable at once
    Warning = 'w',   ///< no effect on the device state
};

/// How an entry goes away: the "Error recovery" of sections 7.1.1 - 7.1.54.
enum class ErrorRecovery {
    FaultReset,  ///< "Reset fault with Controlword"
    ResetDevice, ///< "Reset device": not erasable by a fault reset
    AutoClear,   ///< a warning that clears when its cause is gone
    ClearWarning ///< "Reset warning with Controlword" (the Clear warning command of table 8)
};

/// One row of table 110 "Device error codes".
struct DeviceError {
    std::uint16_t code;
    std::uint8_t error_register; ///< the bits of 0x1001 (table 35)
    std::string_view name;
    FaultReactionCode reaction;
    ErrorRecovery recovery;
};

/// Every row of table 110 except 0x0000 "No Error", in the table's order.
std::span<const DeviceError> device_errors();

/// The row of `code`; a code the table does not list is a programming error
/// (std::invalid_argument).
const DeviceError& device_error(std::uint16_t code);

} // namespace eposp::drives::escon2
