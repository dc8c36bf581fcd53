#pragma once

#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>

namespace eposp::device {

/// An entry of the error history 0x1003 (EPOS P firmware specification 10.4, table 4): the
/// warning bit 31, the port code in bits 27..24 (1 internal, 2 CAN, 0 the controller itself),
/// the node-ID in 23..16 (0 unknown or the master) and the error code of table 1.
struct ErrorEntry {
    std::uint16_t code = 0;
    std::uint8_t port = 0;
    std::uint8_t node = 0;
    bool warning = false;

    std::uint32_t encode() const;
    static ErrorEntry decode(std::uint32_t value);
};

/// Records `error` in 0x1003 (newest first) and sets its bits of the error register 0x1001
/// (table 2: communication for the CAN errors 0x81xx / 0x82xx, generic for the others).
void record_error(canopen::ObjectDictionary& od, const ErrorEntry& error);

} // namespace eposp::device
