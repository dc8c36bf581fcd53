#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/drives/plant/servo_axis.hpp"

#include <array>
#include <cstdint>

namespace eposp::drives::epos2 {

// The plant as the EPOS2's dictionary configures it: encoder pulses and polarity 0x2210
// (8.2.74), the gear 0x2230 (8.2.79), the control parameter sets 0x60F6 / 0x60F9 / 0x60FB
// (8.2.125 - 8.2.127), motor type 0x6402 and motor data 0x6410 (8.2.129, 8.2.130). The physical
// motor (resistance, inductance, constants, inertia), load, gearhead, where the encoder sits,
// supply and switches are not in the dictionary: they come from the simulated machine.

/// The objects whose writes reconfigure the running plant.
inline constexpr std::array<std::uint16_t, 7> kAxisConfigurationObjects = {
    0x2210, 0x2230, 0x60F6, 0x60F9, 0x60FB, 0x6402, 0x6410};

/// Makes the machine's encoder (pulses, direction), gains and motor data the dictionary's
/// defaults (and values).
void write_axis_defaults(canopen::ObjectDictionary& od, const plant::AxisParameters& machine);

/// EPOS2 FW spec 4.2.36, "control function not possible due to controller gains of zero": the
/// loop closes through a controller whose P gain is zero (the position and velocity loops feed
/// the current loop, so its P gain counts for them too). PowerOff needs none.
bool controller_gain_missing(const plant::ServoGains& gains, plant::ControlMode loop);

/// The machine as the dictionary configures it now.
plant::AxisParameters configured_axis(const canopen::ObjectDictionary& od,
                                      plant::AxisParameters machine);

} // namespace eposp::drives::epos2
