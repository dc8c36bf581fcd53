// EPOS P firmware specification 10.20 - 10.30: the network list of CiA 302. Sub-index n is the
// slave with node-ID n on port 2 (1..127), sub-index 128 the internal EPOS2.
#include "eposp/canopen/entry_builder.hpp"
#include "object_areas.hpp"

#include <fmt/format.h>
#include <string>

namespace eposp::device::dictionary {
namespace {

using namespace canopen::od_types;

constexpr int kNetworkListEntries = 0x80;

/// An ARRAY of UNSIGNED32 with one entry per slave, all 0.
void add_per_slave(canopen::ObjectDictionary& od, std::uint16_t index, const std::string& name,
                   bool persistent = true) {
    od.add_object(index, name, kArray);
    for (int sub = 1; sub <= kNetworkListEntries; ++sub) {
        canopen::Entry entry = add_entry(od, index, static_cast<std::uint8_t>(sub),
                                         fmt::format("{} Node {}", name, sub), kU32, kRW, 0);
        if (persistent) {
            entry.persistent();
        }
    }
}

} // namespace

void add_network_list_objects(canopen::ObjectDictionary& od) {
    add_per_slave(od, 0x1F26, "Expected Configuration Date"); // 10.20
    add_per_slave(od, 0x1F27, "Expected Configuration Time"); // 10.21
    // 10.22, table 24: NMT master, start all nodes at once, not self-starting.
    add_var(od, 0x1F80, "NMT Start-up", kU32, kRW, 0x0000'0007).persistent();
    add_per_slave(od, 0x1F81, "Slave Assignment"); // 10.23
    // 10.24: the slaves' NMT states on read, NMT commands on write; the manager gives it both.
    add_per_slave(od, 0x1F82, "Request NMT", false);
    add_per_slave(od, 0x1F84, "Device Type Identification");                         // 10.25
    add_per_slave(od, 0x1F85, "Vendor Identification");                              // 10.26
    add_per_slave(od, 0x1F86, "Product Code");                                       // 10.27
    add_per_slave(od, 0x1F87, "Revision Number");                                    // 10.28
    add_per_slave(od, 0x1F88, "Serial Number");                                      // 10.29
    add_var(od, 0x1F89, "Boot Time", kU32, kRW, 500).range(200, 30000).persistent(); // 10.30
}

} // namespace eposp::device::dictionary
