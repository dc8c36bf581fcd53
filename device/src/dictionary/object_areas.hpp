#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/parameter_store.hpp"
#include "eposp/device/epos_p_dictionary.hpp"

// The areas of the EPOS P dictionary, one file each, in the order of chapter 10.
namespace eposp::device::dictionary {

/// 10.1 - 10.14: 0x1000 - 0x1019.
void add_communication_objects(canopen::ObjectDictionary& od, canopen::ParameterStore& store,
                               const EposPDictionaryConfig& config);
/// 10.15 - 10.19: the SDO clients 0x1280 - 0x12FF and the PDOs 0x1400 - 0x1B03.
void add_sdo_client_and_pdo_objects(canopen::ObjectDictionary& od);
/// 10.20 - 10.30: the network list of CiA 302, 0x1F26 - 0x1F89.
void add_network_list_objects(canopen::ObjectDictionary& od);
/// CiA 302-3 program download: 0x1F50, 0x1F51, 0x1F56, 0x1F57 (beyond chapter 10).
void add_program_objects(canopen::ObjectDictionary& od);
/// 10.31 - 10.37: 0x5000 - 0x5F51, and eposp's variable access 0x5F60.
void add_manufacturer_objects(canopen::ObjectDictionary& od, const EposPDictionaryConfig& config);
/// 10.38 - 10.49: the DS-405 process image, 0xA000 - 0xA680.
void add_process_image_objects(canopen::ObjectDictionary& od);

} // namespace eposp::device::dictionary
