#pragma once

#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <functional>
#include <optional>

namespace eposp::drives::epos2 {

/// EPOS2 FW spec table 8-97 (0x207B) and 8.2.64 (0x207D, bit = code): the set-value
/// functionalities of the analog inputs, each with its configuration object 0x2301 - 0x2303.
enum class AnalogSetpoint : std::uint16_t { Current = 0, Velocity = 1, Position = 2 };

/// 8.2.81 - 8.2.83: Analog Input [V] · Scaling · 10^Notation Index + Offset, in the units of the
/// mode's set value (mA, rpm, qc). The input is the one 0x207B assigns the functionality to;
/// none assigned reads 0 V (the offset alone).
double analog_setpoint(const canopen::ObjectDictionary& od, AnalogSetpoint which);

/// The analog set value that commands the mode instead of its setting value object: when an
/// input is assigned the functionality (0x207B) and the execution mask 0x207D has its bit
/// (5.6, 5.11, 5.13: "setpoint setting is activated by the execution mask and the configuration
/// of the analog input").
std::optional<double> executed_analog_setpoint(const canopen::ObjectDictionary& od,
                                               AnalogSetpoint which);

/// 0x2301 - 0x2303 sub 4, computed when read (SDO, TPDO sampling).
void compute_analog_setpoints(canopen::ObjectDictionary& od);

/// 8.2.62: "a functionality can only be assigned to one of the two analog inputs": 0x207B
/// refuses the other input's value with 0x06040043. (Their "Disable state" rule is
/// guard_disable_state_objects'.)
void guard_analog_input_assignment(canopen::ObjectDictionary& od);

} // namespace eposp::drives::epos2
