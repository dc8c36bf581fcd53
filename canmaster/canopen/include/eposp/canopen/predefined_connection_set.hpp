#pragma once

#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <optional>

namespace eposp::canopen {

// CiA 301 7.3.5: the predefined connection set, the COB-IDs a node derives from its node-ID.

/// RPDO n at 0x200 + 0x100 (n - 1) + node-ID and TPDO n at 0x180 + 0x100 (n - 1) + node-ID for
/// n = 1..4, by the index of the PDO's communication parameter (0x1400.., 0x1800..); nullopt for
/// any other index.
std::optional<std::uint32_t> predefined_pdo_cob_id(std::uint16_t communication_index, NodeId node);

/// The COB-ID the predefined connection set gives the entry `index`:`sub_index`: 0x1014 (EMCY,
/// 0x80 + node-ID), 0x1200 sub 1 and 2 (SDO server, 0x600 / 0x580 + node-ID) and sub 1 of the
/// PDOs above; nullopt for any other entry.
std::optional<std::uint32_t> predefined_cob_id(std::uint16_t index, std::uint8_t sub_index,
                                               NodeId node);

/// Moves the defaults that follow the node-ID from `from` to `to` (LSS gave the node a new one,
/// CiA 305): every entry of predefined_cob_id() whose default names the identifier of `from`
/// names that of `to` instead, its flags (valid, RTR, ...) kept. A default the device chose
/// otherwise stays. The values are left alone: they take the new defaults at the next reset
/// communication, unless a stored value replaces them.
void move_node_id_defaults(ObjectDictionary& od, NodeId from, NodeId to);

} // namespace eposp::canopen
