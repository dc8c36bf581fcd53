#include "eposp/device/epos_p_dictionary.hpp"

#include "eposp/canopen/eds_export.hpp"
#include "object_areas.hpp"

#include <utility>

namespace eposp::device {
namespace {

constexpr std::uint32_t kMaxonVendorId = 0x0000'00FB; // 10.13

constexpr std::uint32_t high_low(std::uint16_t high, std::uint16_t low) {
    return std::uint32_t{high} << 16 | low;
}

} // namespace

canopen::LssAddress epos_p_identity(std::uint32_t serial_number) {
    return {.vendor_id = kMaxonVendorId,
            .product_code = high_low(kHardwareVersion, kApplicationNumber),
            .revision_number = high_low(kSoftwareVersion, kApplicationVersion),
            .serial_number = serial_number};
}

EposPDictionary::EposPDictionary(EposPDictionaryConfig config)
    : config_(std::move(config)), store_(od_, config_.parameter_file) {
    dictionary::add_communication_objects(od_, store_, config_);
    dictionary::add_sdo_client_and_pdo_objects(od_);
    dictionary::add_network_list_objects(od_);
    dictionary::add_program_objects(od_);
    dictionary::add_manufacturer_objects(od_, config_);
    dictionary::add_process_image_objects(od_);
}

canopen::DeviceInfo epos_p_device_info() {
    const canopen::LssAddress identity = epos_p_identity(0);
    canopen::DeviceInfo info;
    info.file.file_name = "epos-p.eds";
    info.file.description = "maxon EPOS P 24/5, simulated by eposp";
    info.file.created_by = "eposp";
    info.vendor_name = "maxon motor ag";
    info.vendor_number = identity.vendor_id;
    info.product_name = "EPOS P 24/5";
    info.product_number = identity.product_code;
    info.revision_number = identity.revision_number;
    info.baud_rates_kbit = {20, 50, 125, 250, 500, 800, 1000}; // table 28
    info.simple_boot_up_master = true;                         // chapter 8: a CANopen manager
    return info;
}

std::string epos_p_eds() {
    // The store is never written: an export only reads the defaults.
    EposPDictionaryConfig config;
    config.parameter_file = "epos-p-parameters.bin";
    const EposPDictionary dictionary(std::move(config));
    return canopen::export_eds(dictionary.objects(), epos_p_device_info());
}

} // namespace eposp::device
