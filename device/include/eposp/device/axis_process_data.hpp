#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/manager/network_list.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace eposp::device {

/// One entry of a process-image object.
struct ImageEntry {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
};

/// Where axis n's process data meets the PLC: one entry of four process-image objects, which
/// the axis PDOs fill and send, and which an ST program can address as well. The image has 16
/// entries per object, so the axes use two sets (docs/network.md, "Axes"):
/// - axes 0..15, entry n + 1 of 0xA100 (statusword, %IW(32+n)), 0xA1C0 (position actual value,
///   %ID(24+n)), 0xA580 (controlword, %QW(32+n)) and 0xA640 (target position, %QD(24+n));
/// - axes 16..31, entry n - 15 of 0xA0C0 (%IW(n)), 0xA200 (%ID(24+n)), 0xA540 (%QW(n)) and
///   0xA680 (%QD(24+n)): the same bits in the objects of the other signedness.
struct AxisChannels {
    ImageEntry statusword;
    ImageEntry actual_position;
    ImageEntry controlword;
    ImageEntry target_position;

    /// The channels of `axis` (0..31).
    static AxisChannels of(std::uint8_t axis);
};

/// The slave side of an axis (docs/network.md, "Axes"), as the writes of a concise DCF in the
/// order CiA 301 7.5.2.35 - 38 asks (PDO invalid, mapping count 0, entries, count, valid):
/// - TPDO 1 (0x180 + node, synchronous): statusword 0x6041, again 0x6041 for the process image,
///   position actual value 0x6064;
/// - RPDO 1 (0x200 + node, applied on receipt): controlword 0x6040, target position 0x607A;
/// - modes of operation 0x6060 = 1, profile position mode.
std::vector<manager::ConfigurationWrite> axis_slave_configuration(canopen::NodeId node);

/// The EPOS P side of the same axis in its dictionary: RPDO `pdo_number` takes the slave's
/// TPDO 1 into the axis table's statusword 0x5280 + axis sub 2 and the axis' channels (applied
/// on receipt, so the PLC task after the SYNC sees them); TPDO `pdo_number` sends the axis'
/// controlword and target position channels at each SYNC. `pdo_number` counts
/// as the port's PdoService does (257 is the first internal PDO).
void configure_axis_pdos(canopen::ObjectDictionary& od, std::size_t pdo_number,
                         canopen::NodeId node, std::uint8_t axis);

} // namespace eposp::device
