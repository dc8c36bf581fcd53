#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/drives/plant/servo_axis.hpp"

#include <array>
#include <cstdint>

namespace eposp::drives::escon2 {

// The plant as the ESCON2's dictionary configures it: encoder pulses 0x3010 sub 1 and direction
// 0x3010 sub 2 bit 4 (6.2.16; it reads right where it matches the machine's mounting), the
// control parameter sets 0x30A0 / 0x30A2 (6.2.18, 6.2.19), the output current limit and pole
// pairs of 0x3001 (6.2.14) and the motor type 0x6402 (6.2.80). The physical motor, load and
// supply are the simulated machine's.
//
// 6.2.18 / 6.2.19 leave the gains' units blank; this model takes maxon's units of the same
// objects on the EPOS4: current P µV/A, I µV/(A·ms); velocity P µA·s/rad, I µA/rad, feed
// forward µA·s/rad and µA·s²/rad (motor-shaft radians).

/// The objects whose writes reconfigure the running plant.
inline constexpr std::array<std::uint16_t, 5> kAxisConfigurationObjects = {0x3001, 0x3010, 0x30A0,
                                                                           0x30A2, 0x6402};

/// Makes the machine's encoder, gains, output current limit, pole pairs and motor type the
/// dictionary's defaults (and values); a brushed motor has no Hall sensor and no commutation
/// sensor (6.2.13.1, 6.2.13.3).
void write_axis_defaults(canopen::ObjectDictionary& od, const plant::AxisParameters& machine);

/// The machine as the dictionary configures it now.
plant::AxisParameters configured_axis(const canopen::ObjectDictionary& od,
                                      plant::AxisParameters machine);

} // namespace eposp::drives::escon2
