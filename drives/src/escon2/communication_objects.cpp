// The communication objects of the ESCON2 (firmware specification 6.2.1 - 6.2.7). The error
// history and store / restore come from canmaster's services, under the ESCON2's names.
#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/store_restore_objects.hpp"
#include "object_areas.hpp"

#include <fmt/format.h>

namespace eposp::drives::escon2 {
namespace {

using namespace canopen::od_types;
using canopen::DataType;

void rename_object(canopen::ObjectDictionary& od, std::uint16_t index, std::string name) {
    od.find(index)->name = std::move(name);
}

// 6.2.1 - 6.2.4
void add_device_and_error_objects(canopen::ObjectDictionary& od) {
    add_var(od, 0x1000, "Device type", kU32, kRO, kDeviceType);
    canopen::add_error_objects(od, canopen::kEpos2ErrorHistoryEntries); // 6.2.3: five entries
    existing_entry(od, 0x1001, 0, "Error register");
    rename_object(od, 0x1003, "Error history");
    existing_entry(od, 0x1003, 0, "Number of errors");
    for (std::uint8_t sub = 1; sub <= canopen::kEpos2ErrorHistoryEntries; ++sub) {
        existing_entry(od, 0x1003, sub, fmt::format("Error history {}", sub));
    }
    od.add_variable(0x1008, "Manufacturer device name", DataType::VisibleString, kRO,
                    canopen::encode_string("ESCON2"));
}

// 6.2.5 / 6.2.6: "save" and "load"; a restore only in «Power Disable».
void add_store_restore(canopen::ObjectDictionary& od, canopen::ParameterStore& store,
                       const Escon2DictionaryConfig& config) {
    canopen::add_store_restore_objects(
        od, store, {.restore_permitted = [power_disabled = config.power_disabled] {
            return !power_disabled || power_disabled() ? canopen::AbortCode::None
                                                       : canopen::AbortCode::DeviceState;
        }});
    rename_object(od, 0x1010, "Store parameters");
    existing_entry(od, 0x1010, 1, "Save all parameters");
    rename_object(od, 0x1011, "Restore default parameters");
    existing_entry(od, 0x1011, 1, "Restore all default parameters");
}

// 6.2.7
void add_identity_object(canopen::ObjectDictionary& od, const canopen::LssAddress& identity) {
    od.add_object(0x1018, "Identity object", kRecord);
    add_entry(od, 0x1018, 1, "Vendor ID", kU32, kRO, identity.vendor_id);
    add_entry(od, 0x1018, 2, "Product code", kU32, kRO, identity.product_code);
    add_entry(od, 0x1018, 3, "Revision number", kU32, kRO, identity.revision_number);
    add_entry(od, 0x1018, 4, "Serial number", kU32, kRO, identity.serial_number);
}

} // namespace

void add_communication_objects(canopen::ObjectDictionary& od, canopen::ParameterStore& store,
                               const Escon2DictionaryConfig& config) {
    add_device_and_error_objects(od);
    add_store_restore(od, store, config);
    add_identity_object(od, escon2_identity(config.hardware, config.serial_number));
}

} // namespace eposp::drives::escon2
