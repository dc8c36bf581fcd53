#include "eposp/drives/escon2/escon2_dictionary.hpp"

#include "object_areas.hpp"

#include <utility>

namespace eposp::drives::escon2 {
namespace {

constexpr std::uint32_t high_low(std::uint16_t high, std::uint16_t low) {
    return std::uint32_t{high} << 16 | low;
}

} // namespace

canopen::LssAddress escon2_identity(Escon2Hardware hardware, std::uint64_t serial_number) {
    return {.vendor_id = kMaxonVendorId,
            .product_code = high_low(hardware_data(hardware).hardware_version, kApplicationNumber),
            .revision_number = high_low(kSoftwareVersion, kApplicationVersion),
            .serial_number = static_cast<std::uint32_t>(serial_number)};
}

void only_in_power_disable(canopen::Entry entry, const Escon2DictionaryConfig& config) {
    entry.rule([power_disabled = config.power_disabled](std::span<const std::uint8_t>) {
        return !power_disabled || power_disabled() ? canopen::AbortCode::None
                                                   : canopen::AbortCode::DeviceState;
    });
}

Escon2Dictionary::Escon2Dictionary(Escon2DictionaryConfig config)
    : config_(std::move(config)), store_(od_, config_.parameter_file) {
    add_communication_objects(od_, store_, config_);
    add_device_objects(od_, config_);
    add_io_objects(od_, config_);
    add_profile_objects(od_, config_);
}

canopen::StoredValuesReport Escon2Dictionary::power_up() {
    return store_.load_stored_values();
}

canopen::DeviceInfo escon2_device_info(Escon2Hardware hardware) {
    const canopen::LssAddress identity = escon2_identity(hardware, 0);
    canopen::DeviceInfo info;
    info.file.file_name = "escon2.eds";
    info.file.description = "maxon ESCON2, simulated by eposp";
    info.file.created_by = "eposp";
    info.vendor_name = "maxon motor ag";
    info.vendor_number = identity.vendor_id;
    info.product_name = std::string(hardware_data(hardware).product_name);
    info.product_number = identity.product_code;
    info.revision_number = identity.revision_number;
    info.granularity = 0; // no PDOs: the ESCON2 has no CAN (chapter 5)
    return info;
}

} // namespace eposp::drives::escon2
