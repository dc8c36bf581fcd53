// EPOS P firmware specification 10.15 - 10.19: the SDO clients and the PDOs, 32 of each
// direction for port 2 and 4 for the internal port.
#include "eposp/canopen/entry_builder.hpp"
#include "eposp/canopen/pdo_objects.hpp"
#include "object_areas.hpp"

#include <fmt/format.h>

namespace eposp::device::dictionary {
namespace {

using namespace canopen::od_types;

constexpr std::uint32_t kPdoOff = 0xC000'0000; ///< not valid, no RTR (tables 13, 18)
constexpr std::size_t kExternalPdos = 32;
constexpr std::size_t kInternalPdos = 4;

// 10.15: 0x1280 is the client of the internal EPOS2, 0x1281 + n - 1 that of node n on port 2.
// The server's node-ID is fixed; the COB-IDs follow it.
void add_sdo_clients(canopen::ObjectDictionary& od) {
    for (int n = 0; n <= 127; ++n) {
        const auto index = static_cast<std::uint16_t>(0x1280 + n);
        const std::int64_t server = n == 0 ? 1 : n;
        od.add_object(index, fmt::format("SDO Client Parameter {}", n + 1), kRecord);
        add_entry(od, index, 1, "COB-ID client to server", kU32, kRW, 0x600 + server).persistent();
        add_entry(od, index, 2, "COB-ID server to client", kU32, kRW, 0x580 + server).persistent();
        add_entry(od, index, 3, "Server Node-ID", kU8, kRW, server).range(server, server);
    }
}

// 10.16 - 10.19: `count` PDOs each way from PDO `first_number` on, all off, event-driven, TPDOs
// with an inhibit time of 1 ms; 11-bit CAN-IDs 0x181..0x57F, 8 mapping entries, no RPDO
// deadline and no SYNC start value.
canopen::PdoObjectsConfig epos_p_pdos(std::size_t first_number, std::size_t count) {
    canopen::PdoObjectsConfig config;
    canopen::PdoDefaults off;
    off.cob_id = kPdoOff;
    off.transmission_type = 255;
    config.rpdos.assign(count, off);
    off.inhibit_time = 10;
    config.tpdos.assign(count, off);
    config.mapping_entries = 8;
    config.rpdo_event_timer = false;
    config.tpdo_sync_start = false;
    config.extended_ids = false;
    config.can_id_range = canopen::CanIdRange{0x181, 0x57F};
    config.first_number = first_number;
    config.rpdo_transmission_types = {1, 255};      // table 15
    config.tpdo_transmission_types = {1, 253, 255}; // table 20
    return config;
}

} // namespace

void add_sdo_client_and_pdo_objects(canopen::ObjectDictionary& od) {
    add_sdo_clients(od);
    canopen::add_pdo_objects(od, epos_p_pdos(1, kExternalPdos));
    // The first internal RPDO takes the internal EPOS2's TPDO 1 (its statusword, 0x181) into
    // axis 0's statusword (10.16, 10.17: 0x1500 = 0x181, 0x1700 = 0x52800210).
    canopen::PdoObjectsConfig internal = epos_p_pdos(kFirstInternalPdo, kInternalPdos);
    internal.rpdos[0].cob_id = 0x181;
    internal.rpdos[0].mapping = {0x5280'0210};
    canopen::add_pdo_objects(od, internal);
    // The internal PDOs are numbered 1..4 of their own port (10.16 - 10.19).
    for (std::size_t n = 1; n <= kInternalPdos; ++n) {
        const std::size_t number = kFirstInternalPdo + n - 1;
        for (const auto direction :
             {canopen::PdoDirection::Receive, canopen::PdoDirection::Transmit}) {
            const std::string pdo = fmt::format(
                "{} PDO {} internal",
                direction == canopen::PdoDirection::Receive ? "Receive" : "Transmit", n);
            od.find(canopen::pdo_communication_index(direction, number))->name = pdo + " Parameter";
            od.find(canopen::pdo_mapping_index(direction, number))->name = pdo + " Mapping";
        }
    }
}

} // namespace eposp::device::dictionary
