#include "eposp/drives/epos2/epos2_dictionary.hpp"

#include "eposp/canopen/lss_protocol.hpp"
#include "object_areas.hpp"
#include "verify_configuration.hpp"

#include <utility>
#include <vector>

namespace eposp::drives::epos2 {
namespace {

constexpr std::uint32_t high_low(std::uint16_t high, std::uint16_t low) {
    return std::uint32_t{high} << 16 | low;
}

// Table 8-77: every read-write object of table 8-67 that PDOs may map is a receive PDO object
// (none is mapped by transmit PDOs only). CiA 306 writes that access as rww, as maxon's EDS does;
// it reads and writes like rw.
void mark_receive_pdo_objects(canopen::ObjectDictionary& od) {
    std::vector<std::pair<std::uint16_t, std::uint8_t>> outputs;
    for (const auto& [index, object] : od.objects()) {
        for (const auto& [sub_index, sub] : object.subs) {
            if (sub.access == canopen::Access::ReadWrite && sub.pdo_mappable) {
                outputs.emplace_back(index, sub_index);
            }
        }
    }
    for (const auto& [index, sub_index] : outputs) {
        od.find(index, sub_index)->access = canopen::Access::ReadWriteOutput;
    }
}

} // namespace

canopen::LssAddress epos2_identity(std::uint64_t serial_number) {
    return {.vendor_id = kMaxonVendorId,
            .product_code = high_low(kHardwareVersion, kApplicationNumber),
            .revision_number = high_low(kSoftwareVersion, kApplicationVersion),
            .serial_number = static_cast<std::uint32_t>(serial_number)};
}

Epos2Dictionary::Epos2Dictionary(Epos2DictionaryConfig config)
    : config_(std::move(config)), store_(od_, config_.parameter_file) {
    add_communication_objects(od_, store_, config_);
    add_manufacturer_objects(od_, config_);
    add_profile_objects(od_);
    mark_receive_pdo_objects(od_);
    watch_verified_configuration(od_);
}

canopen::NodeConfig Epos2Dictionary::node_config() const {
    canopen::NodeConfig node;
    node.node_id = config_.node_id;
    node.bit_rate = config_.bit_rate;
    node.device_type = kDeviceType;
    node.identity = epos2_identity(config_.serial_number);
    node.parameter_file = config_.parameter_file;
    // Table 4-11 gives each error its register value (overcurrent 0000 0010b, not 0000 0011b).
    node.generic_error_bit = canopen::GenericErrorBit::FromTheTable;
    return node;
}

canopen::DeviceInfo epos2_device_info() {
    const canopen::LssAddress identity = epos2_identity(0);
    canopen::DeviceInfo info;
    info.file.file_name = "epos2.eds";
    info.file.description = "maxon EPOS2 24/5, simulated by eposp";
    info.file.created_by = "eposp";
    info.vendor_name = "maxon motor ag";
    info.vendor_number = identity.vendor_id;
    info.product_name = "EPOS2 24/5";
    info.product_number = identity.product_code;
    info.revision_number = identity.revision_number;
    info.baud_rates_kbit = {20, 50, 125, 250, 500, 800, 1000}; // table 8-81
    info.simple_boot_up_slave = true;
    info.lss_supported = true;
    return info;
}

std::optional<std::uint16_t> bit_rate_code(std::uint32_t bit_rate) {
    // Table 8-81 is CiA's bit timing table, but for code 8: "not supported (10 kbit/s)".
    constexpr std::uint8_t kTenKbitCode = 8;
    const auto index = canopen::lss_bit_timing_index(bit_rate);
    if (!index || *index == kTenKbitCode) {
        return std::nullopt;
    }
    return *index;
}

} // namespace eposp::drives::epos2
