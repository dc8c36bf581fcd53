#pragma once

#include "eposp/drives/motion/device_control.hpp"

#include <cstdint>
#include <span>
#include <string_view>

namespace eposp::drives::epos2 {

/// One row of EPOS2 FW spec table 4-11 "Error Codes – Overview".
struct DeviceError {
    std::uint16_t code;
    std::uint8_t error_register; ///< the bits of 0x1001 the error sets
    /// "a" Abort Connection Option Code, "f" Fault Reaction Option Code, "d" always disable.
    motion::FaultClass reaction;
    bool position_reset; ///< clearing the error resets the actual position
    std::string_view name;
};

/// Every row of table 4-11 except 0x0000 "No Error", in the table's order.
std::span<const DeviceError> device_errors();

/// The row of `code`; a code the table does not list is a programming error
/// (std::invalid_argument).
const DeviceError& device_error(std::uint16_t code);

} // namespace eposp::drives::epos2
