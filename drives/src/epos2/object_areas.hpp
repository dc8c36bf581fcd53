#pragma once

#include "eposp/drives/epos2/epos2_dictionary.hpp"

namespace eposp::drives::epos2 {

// The three areas of the EPOS2 dictionary (CiA 301 7.4.1), one file each, in table 8-67 order.

/// 0x1000 - 0x1A03 (8.2.1 - 8.2.33), through canmaster's services where one owns the object.
void add_communication_objects(canopen::ObjectDictionary& od, canopen::ParameterStore& store,
                               const Epos2DictionaryConfig& config);
/// 0x2000 - 0x2303 (8.2.34 - 8.2.83).
void add_manufacturer_objects(canopen::ObjectDictionary& od, const Epos2DictionaryConfig& config);
/// 0x6007 - 0x6502 (8.2.84 - 8.2.131), with the units and factor group objects of 3.3.
void add_profile_objects(canopen::ObjectDictionary& od);

} // namespace eposp::drives::epos2
