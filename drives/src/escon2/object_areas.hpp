#pragma once

#include "eposp/canopen/entry_builder.hpp"
#include "eposp/drives/escon2/escon2_dictionary.hpp"

namespace eposp::drives::escon2 {

// The ESCON2 dictionary (FW spec table 34) in four files, each in the table's order.

/// 0x1000 - 0x1018 (6.2.1 - 6.2.7).
void add_communication_objects(canopen::ObjectDictionary& od, canopen::ParameterStore& store,
                               const Escon2DictionaryConfig& config);
/// 0x2100 - 0x30F1 and 0x3200 - 0x3203 (6.2.8 - 6.2.25, 6.2.55 - 6.2.57).
void add_device_objects(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config);
/// 0x3141 - 0x31C3 (6.2.26 - 6.2.54): the inputs and outputs.
void add_io_objects(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config);
/// 0x603F - 0x6502 (6.2.58 - 6.2.81).
void add_profile_objects(canopen::ObjectDictionary& od, const Escon2DictionaryConfig& config);

/// "Write access is only permitted in device state «Power Disable»": 0x08000022 otherwise.
void only_in_power_disable(canopen::Entry entry, const Escon2DictionaryConfig& config);

} // namespace eposp::drives::escon2
