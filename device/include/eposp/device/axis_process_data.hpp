#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/manager/network_list.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace eposp::device {

/// Where axis n's process data meets the PLC: entry n + 1 of four process-image objects. Only
/// axes 0..15 have them (the process image has 16 entries per object).
struct AxisChannels {
    std::uint8_t sub_index = 0;
    /// The byte offsets the ST program addresses: %IW(32+n), %ID(24+n), %QW(32+n), %QD(24+n).
    std::uint32_t statusword_word = 0;
    std::uint32_t actual_position_dword = 0;
    std::uint32_t controlword_word = 0;
    std::uint32_t target_position_dword = 0;

    /// The channels of `axis`, or none for axes 16..31.
    static std::optional<AxisChannels> of(std::uint8_t axis);
};

/// The process image objects of AxisChannels (EPOS P 10.38 - 10.49).
inline constexpr std::uint16_t kStatuswordInputs = 0xA100;     ///< UNSIGNED16 inputs
inline constexpr std::uint16_t kActualPositionInputs = 0xA1C0; ///< INTEGER32 inputs
inline constexpr std::uint16_t kControlwordOutputs = 0xA580;   ///< UNSIGNED16 outputs
inline constexpr std::uint16_t kTargetPositionOutputs = 0xA640; ///< INTEGER32 outputs

/// The slave side of an axis (docs/network.md, "Axes"), as the writes of a concise DCF in the
/// order CiA 301 7.5.2.35 - 38 asks (PDO invalid, mapping count 0, entries, count, valid):
/// - TPDO 1 (0x180 + node, synchronous): statusword 0x6041, again 0x6041 for the process image,
///   position actual value 0x6064; axes 16..31 only the statusword;
/// - RPDO 1 (0x200 + node, applied on receipt): controlword 0x6040, target position 0x607A;
///   axes 16..31 have no RPDO set up;
/// - modes of operation 0x6060 = 1, profile position mode.
std::vector<manager::ConfigurationWrite> axis_slave_configuration(canopen::NodeId node,
                                                                  std::uint8_t axis);

/// The EPOS P side of the same axis in its dictionary: RPDO `pdo_number` takes the slave's
/// TPDO 1 into the axis table's statusword 0x5280 + axis sub 2 and the axis' channels (applied
/// on receipt, so the PLC task after the SYNC sees them); for axes 0..15 TPDO `pdo_number`
/// sends the axis' controlword and target position channels at each SYNC. `pdo_number` counts
/// as the port's PdoService does (257 is the first internal PDO).
void configure_axis_pdos(canopen::ObjectDictionary& od, std::size_t pdo_number,
                         canopen::NodeId node, std::uint8_t axis);

} // namespace eposp::device
