#pragma once

#include "eposp/canopen/object_dictionary.hpp"

namespace eposp::drives::epos2 {

/// EPOS2 FW spec 8.2.16: a change of any persistent parameter that table 8-67 does not put in
/// brackets resets 0x1020 "Verify Configuration" (date and time) to 0, so that a master sees
/// that the configuration it stored is no longer the one in the device. Call once every object
/// is in the dictionary.
void watch_verified_configuration(canopen::ObjectDictionary& od);

} // namespace eposp::drives::epos2
