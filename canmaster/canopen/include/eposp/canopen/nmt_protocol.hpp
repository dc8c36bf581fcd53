#pragma once

#include "eposp/canopen/nmt_state.hpp"

#include <cstdint>
#include <optional>

namespace eposp::canopen {

// Network management, CiA 301 7.2.8 (EPOS2 FW spec 7.3): the identifiers, command specifiers
// and state bytes that the NMT slave and master, heartbeat and node guarding share.

/// NMT node control: COB-ID 0x000, two bytes, the command specifier and the node-ID.
inline constexpr std::uint32_t kNmtCanId = 0x000;
/// Heartbeat, boot-up and node-guarding frames of a node share 0x700 + node-ID (7.2.8.3.2).
inline constexpr std::uint32_t kErrorControlCanIdBase = 0x700;

constexpr std::uint32_t error_control_can_id(NodeId node) {
    return kErrorControlCanIdBase + node;
}

/// The node control commands by their command specifier (7.2.8.3.1; EPOS2 FW spec 7.3).
enum class NmtCommand : std::uint8_t {
    Start = 0x01,
    Stop = 0x02,
    EnterPreOperational = 0x80,
    ResetNode = 0x81,
    ResetCommunication = 0x82,
};

/// The node-ID an NMT command addresses to every slave.
inline constexpr NodeId kAllNodes = 0;
inline constexpr NodeId kMaxNodeId = 127;

constexpr bool is_nmt_command(std::uint8_t specifier) {
    switch (static_cast<NmtCommand>(specifier)) {
    case NmtCommand::Start:
    case NmtCommand::Stop:
    case NmtCommand::EnterPreOperational:
    case NmtCommand::ResetNode:
    case NmtCommand::ResetCommunication:
        return true;
    }
    return false;
}

/// The state in bits 6..0 of a heartbeat or node-guarding byte (7.2.8.3.2.1); nullopt for a
/// value CiA 301 does not define. Bit 7 is the guarding toggle bit, 0 in a heartbeat.
constexpr std::optional<NmtState> decode_nmt_state(std::uint8_t bits) {
    switch (static_cast<NmtState>(bits)) {
    case NmtState::Initialising:
    case NmtState::Stopped:
    case NmtState::Operational:
    case NmtState::PreOperational:
        return static_cast<NmtState>(bits);
    }
    return std::nullopt;
}

} // namespace eposp::canopen
