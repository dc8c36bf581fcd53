#include "eposp/drives/escon2/units.hpp"

#include <cmath>

namespace eposp::drives::escon2 {

UserDefinedUnit decode_unit(std::uint32_t code) {
    return {.prefix = static_cast<std::int8_t>(code >> 24),
            .numerator = static_cast<std::uint8_t>(code >> 16),
            .denominator = static_cast<std::uint8_t>(code >> 8)};
}

double velocity_unit_in_rpm(std::uint32_t si_unit_velocity) {
    return std::pow(10.0, decode_unit(si_unit_velocity).prefix);
}

} // namespace eposp::drives::escon2
