// The communication area of the EPOS2 (firmware specification 8.2.1 - 8.2.33). Objects that a
// canmaster service owns are added by that service, with the write rules and hooks the service
// needs, and then given the EPOS2's names and attributes; the rest is data.
#include "eposp/canopen/emcy_producer.hpp"
#include "eposp/canopen/entry_builder.hpp"
#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/heartbeat_consumer.hpp"
#include "eposp/canopen/heartbeat_producer.hpp"
#include "eposp/canopen/node_guarding.hpp"
#include "eposp/canopen/pdo_objects.hpp"
#include "eposp/canopen/sdo_server.hpp"
#include "eposp/canopen/sync_objects.hpp"
#include "object_areas.hpp"

#include <array>
#include <fmt/format.h>
#include <string>
#include <utility>

namespace eposp::drives::epos2 {
namespace {

using canopen::Access;
using canopen::DataType;
using canopen::Entry;
using canopen::ObjectCode;

constexpr std::uint8_t kHeartbeatConsumers = 2;  // 8.2.13
constexpr std::uint32_t kTimeStampCobId = 0x100; // 8.2.10: fixed

void rename_object(canopen::ObjectDictionary& od, std::uint16_t index, std::string name) {
    od.find(index)->name = std::move(name);
}

// 8.2.1 - 8.2.7
void add_device_and_error_objects(canopen::ObjectDictionary& od) {
    add_var(od, 0x1000, "Device Type", DataType::Unsigned32, Access::ReadOnly, kDeviceType);
    canopen::add_error_objects(od, canopen::kEpos2ErrorHistoryEntries);
    rename_object(od, 0x1003, "Error History");
    for (std::uint8_t sub = 1; sub <= canopen::kEpos2ErrorHistoryEntries; ++sub) {
        existing_entry(od, 0x1003, sub, fmt::format("Error History [{}]", sub));
    }
    // 8.2.4: value range "80 80"; the EPOS2 produces no SYNC.
    canopen::add_sync_objects(od, {.producer = false, .window = false});
    existing_entry(od, 0x1005, 0, "COB-ID SYNC").range(0x80, 0x80);
    od.add_variable(0x1008, "Manufacturer Device Name", DataType::VisibleString, Access::Const,
                    canopen::encode_string("EPOS2"));
    canopen::add_node_guarding_objects(od);
    existing_entry(od, 0x100C, 0, "Guard Time").range(0, 65535);
    existing_entry(od, 0x100D, 0, "Lifetime Factor").range(0, 255);
}

// 8.2.8 / 8.2.9: the Node of canmaster finds these present and keeps them.
void add_store_restore(canopen::ObjectDictionary& od, canopen::ParameterStore& store,
                       const Epos2DictionaryConfig& config) {
    canopen::add_store_restore_objects(od, store, config.restore);
    canopen::add_restore_pdo_cob_ids_object(
        od, store, [&od] { return od.get_as<std::uint8_t>(0x2000, 0); }, config.restore);
}

// 8.2.10 - 8.2.14
void add_time_emcy_heartbeat_objects(canopen::ObjectDictionary& od, canopen::NodeId node) {
    // 8.2.10 / 8.2.11: the time stamp objects are data; no TIME service consumes them.
    add_var(od, 0x1012, "COB-ID Time Stamp Object", DataType::Unsigned32, Access::ReadWrite,
            kTimeStampCobId)
        .range(kTimeStampCobId, kTimeStampCobId)
        .persistent();
    add_var(od, 0x1013, "High Resolution Time Stamp", DataType::Unsigned32, Access::ReadWrite, 0)
        .pdo_mappable();
    canopen::add_emcy_objects(od, node, /*inhibit_time=*/false); // no 0x1015 on the EPOS2
    canopen::add_heartbeat_consumer_objects(od, kHeartbeatConsumers);
    for (std::uint8_t sub = 1; sub <= kHeartbeatConsumers; ++sub) {
        existing_entry(od, 0x1016, sub, fmt::format("Consumer {} Heartbeat Time", sub));
    }
    canopen::add_heartbeat_producer_object(od);
}

// 8.2.15 / 8.2.16
void add_identity_objects(canopen::ObjectDictionary& od, const canopen::LssAddress& identity) {
    od.add_object(0x1018, "Identity Object", ObjectCode::Record);
    const auto id = [&od](std::uint8_t sub, std::string name, std::uint32_t value) {
        add_entry(od, 0x1018, sub, std::move(name), DataType::Unsigned32, Access::ReadOnly, value);
    };
    id(1, "Vendor ID", identity.vendor_id);
    id(2, "Product Code", identity.product_code);
    id(3, "Revision Number", identity.revision_number);
    id(4, "Serial Number", identity.serial_number);

    od.add_object(0x1020, "Verify Configuration", ObjectCode::Array);
    add_entry(od, 0x1020, 1, "Configuration Date", DataType::Unsigned32, Access::ReadWrite, 0)
        .persistent();
    add_entry(od, 0x1020, 2, "Configuration Time", DataType::Unsigned32, Access::ReadWrite, 0)
        .persistent();
}

// 8.2.17 - 8.2.33: canmaster's EPOS2 PDO defaults are those of these sections.
void add_sdo_and_pdo_objects(canopen::ObjectDictionary& od, canopen::NodeId node) {
    canopen::add_sdo_server_objects(od, node);
    canopen::add_pdo_objects(od, canopen::epos2_pdo_defaults(node));
    constexpr std::array kOrdinals = {"1st", "2nd", "3rd", "4th", "5th", "6th", "7th", "8th"};
    for (const auto direction : {canopen::PdoDirection::Receive, canopen::PdoDirection::Transmit}) {
        const bool receive = direction == canopen::PdoDirection::Receive;
        const std::string kind = receive ? "Receive" : "Transmit";
        for (std::size_t n = 1; n <= 4; ++n) {
            const auto parameter = canopen::pdo_communication_index(direction, n);
            rename_object(od, parameter, fmt::format("{} PDO {} Parameter", kind, n));
            existing_entry(od, parameter, canopen::kPdoCobIdSub,
                           fmt::format("COB-ID {} PDO {}", kind, n));
            existing_entry(od, parameter, canopen::kPdoTransmissionTypeSub,
                           fmt::format("Transmission Type {} PDO {}", kind, n));
            if (!receive) {
                existing_entry(od, parameter, canopen::kPdoInhibitTimeSub,
                               fmt::format("Inhibit Time {} PDO {}", kind, n));
            }
            const auto mapping = canopen::pdo_mapping_index(direction, n);
            rename_object(od, mapping, fmt::format("{} PDO {} Mapping", kind, n));
            existing_entry(od, mapping, 0,
                           fmt::format("Number of mapped Application Objects in {} PDO", kind));
            for (std::uint8_t sub = 1; sub <= kOrdinals.size(); ++sub) {
                existing_entry(od, mapping, sub,
                               fmt::format("{} mapped Object", kOrdinals[sub - 1]));
            }
        }
    }
}

} // namespace

void add_communication_objects(canopen::ObjectDictionary& od, canopen::ParameterStore& store,
                               const Epos2DictionaryConfig& config) {
    add_device_and_error_objects(od);
    add_store_restore(od, store, config);
    add_time_emcy_heartbeat_objects(od, config.node_id);
    add_identity_objects(od, epos2_identity(config.serial_number));
    add_sdo_and_pdo_objects(od, config.node_id);
}

} // namespace eposp::drives::epos2
