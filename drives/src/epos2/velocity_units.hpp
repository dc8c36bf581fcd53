#pragma once

#include "eposp/canopen/object_dictionary.hpp"

#include <cmath>
#include <cstdint>

namespace eposp::drives::epos2 {

/// 3.3, tables 3-7 and 3-9: the velocity unit is rpm × 10^(Velocity Notation Index 0x608B,
/// -3 … 0), so that -1 gives the velocity objects a resolution of 0.1 rpm. The acceleration unit
/// keeps its own notation index (0x608D, 0 only): rpm/s whatever 0x608B is.
inline double rpm_per_velocity_unit(const canopen::ObjectDictionary& od) {
    return std::pow(10.0, od.get_as<std::int8_t>(0x608B, 0));
}

/// 8.2.79, 8.2.74: motor turns per turn of the main sensor, which sits on the gear's output when
/// a gear is configured (numerator 0x2230 sub 1 not 0): numerator / denominator; 1 without one.
inline double motor_turns_per_sensor_turn(const canopen::ObjectDictionary& od) {
    const auto numerator = od.get_as<std::uint32_t>(0x2230, 1);
    return numerator == 0 ? 1.0
                          : static_cast<double>(numerator) / od.get_as<std::uint16_t>(0x2230, 2);
}

} // namespace eposp::drives::epos2
