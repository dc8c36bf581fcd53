#pragma once

#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <functional>
#include <span>

namespace eposp::drives::epos2 {

/// The objects chapter 8 marks "Changes are only supported in 'Disable' state" or "Can only be
/// changed in 'Disable' state": 0x2008 (8.2.41), 0x207B (8.2.62), 0x2210 - 0x2213
/// (8.2.74 - 8.2.77), 0x2220 (8.2.78), 0x2230 (8.2.79), 0x2301 - 0x2303 (8.2.81 - 8.2.83), the
/// factor group 0x6089 - 0x608E (8.2.112 - 8.2.117), 0x6402 (8.2.129) and 0x6410 sub 3 (8.2.130).
/// A write that changes one of their writable entries while `power_stage_on()` is refused with
/// 0x08000022 "wrong device state" (table 4-12); writing the present value changes nothing and is
/// accepted. (0x2079 has its own rule for the holding brake, Epos2Io.)
void guard_disable_state_objects(canopen::ObjectDictionary& od,
                                 std::function<bool()> power_stage_on);

/// 8.2.79: "For some combinations of sensor type/motor type, a gear is not allowed. In this case,
/// only gear numerator value 0 (zero: no gear) is permitted" (table 8-103, *A and *B). Any other
/// numerator is refused then with 0x06040043 "general parameter incompatibility" (table 4-12).
void guard_gear_configuration(canopen::ObjectDictionary& od);

} // namespace eposp::drives::epos2
