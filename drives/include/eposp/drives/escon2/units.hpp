#pragma once

#include <cstdint>

namespace eposp::drives::escon2 {

/// ESCON2 FW spec 2.3, table 10: a user-defined unit as 0x60A9 / 0x60AA code it.
struct UserDefinedUnit {
    std::int8_t prefix;       ///< bits 31 … 24: a power of ten (table 13: 0xFD is milli)
    std::uint8_t numerator;   ///< bits 23 … 16: a notation index of tables 11 / 12
    std::uint8_t denominator; ///< bits 15 … 8
};

UserDefinedUnit decode_unit(std::uint32_t code);

/// The velocity unit of 0x60A9 in rpm: 1 for rev/min (0x00B44700), 0.001 for milli rev/min
/// (0xFDB44700); the acceleration unit of 0x60AA is rpm/s (table 105), whatever the velocity's.
double velocity_unit_in_rpm(std::uint32_t si_unit_velocity);

} // namespace eposp::drives::escon2
