// EPOS P firmware specification 10.1 - 10.14: 0x1000 - 0x1019.
#include "eposp/canopen/entry_builder.hpp"
#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/heartbeat_consumer.hpp"
#include "eposp/canopen/store_restore_objects.hpp"
#include "eposp/canopen/sync_objects.hpp"
#include "object_areas.hpp"

#include <fmt/format.h>

namespace eposp::device::dictionary {
namespace {

using namespace canopen::od_types;

// 10.11, table 10: one entry per possible producer, 1..127 on port 2 and 128 the internal EPOS2;
// port code in bits 31..24, node-ID in 23..16, time in ms in 15..0.
void add_consumer_heartbeat_time(canopen::ObjectDictionary& od) {
    canopen::add_heartbeat_consumer_objects(od, 0x80);
    for (int sub = 1; sub <= 0x80; ++sub) {
        existing_entry(od, canopen::kConsumerHeartbeatTimeIndex, static_cast<std::uint8_t>(sub),
                       fmt::format("Consumer Heartbeat Time Node {}", sub))
            .persistent();
    }
}

void add_identity(canopen::ObjectDictionary& od, std::uint32_t serial_number) {
    const canopen::LssAddress identity = epos_p_identity(serial_number);
    od.add_object(0x1018, "Identity Object", kRecord);
    add_entry(od, 0x1018, 1, "Vendor ID", kU32, kRO, identity.vendor_id);
    add_entry(od, 0x1018, 2, "Product Code", kU32, kRO, identity.product_code);
    add_entry(od, 0x1018, 3, "Revision Number", kU32, kRO, identity.revision_number);
    add_entry(od, 0x1018, 4, "Serial Number", kU32, kRO, identity.serial_number);
}

} // namespace

void add_communication_objects(canopen::ObjectDictionary& od, canopen::ParameterStore& store,
                               const EposPDictionaryConfig& config) {
    add_var(od, 0x1000, "Device Type", kU32, kRO, kDeviceType);         // 10.1
    canopen::add_error_objects(od, canopen::kEposPErrorHistoryEntries); // 10.2, 10.4
    od.find(0x1003)->name = "Error History";
    for (std::uint8_t sub = 1; sub <= canopen::kEposPErrorHistoryEntries; ++sub) {
        existing_entry(od, 0x1003, sub, fmt::format("Error History ({})", sub));
    }
    add_var(od, 0x1002, "Manufacturer Status Register", kU32, kRO, 0); // 10.3
    // 10.5 - 10.7, 10.14: the EPOS P produces SYNC; its cycle is 0 (off) or at least 1 ms, its
    // window 0 (none) or at least 0.5 ms.
    canopen::add_sync_objects(od, {.producer = true,
                                   .window = true,
                                   .min_cycle_period_us = 1000,
                                   .min_window_length_us = 500});
    existing_entry(od, canopen::kCobIdSyncIndex, 0, "COB-ID SYNC Message").persistent();
    existing_entry(od, canopen::kCommunicationCyclePeriodIndex, 0, "Communication Cycle Time")
        .persistent();
    existing_entry(od, canopen::kSynchronousWindowLengthIndex, 0, "Synchronous Window Length")
        .persistent();
    existing_entry(od, canopen::kSyncCounterOverflowIndex, 0, "Synchronous Counter").persistent();
    od.add_variable(0x1008, "Device Name", canopen::DataType::VisibleString, kConst,
                    canopen::encode_string("EPOS P"));             // 10.8
    canopen::add_store_restore_objects(od, store, config.restore); // 10.9, 10.10
    existing_entry(od, 0x1010, 1, "Save All Parameters");
    existing_entry(od, 0x1011, 1, "Restore All Default Parameters");
    canopen::add_erase_program_object(
        od, config.erase_program ? config.erase_program
                                 : [] { return canopen::AbortCode::TransferOrStore; });
    add_consumer_heartbeat_time(od);                                           // 10.11
    add_var(od, 0x1017, "Producer Heartbeat Time", kU16, kRW, 0).persistent(); // 10.12
    add_identity(od, config.serial_number);                                    // 10.13
}

} // namespace eposp::device::dictionary
