#pragma once

#include "eposp/service/commands.hpp"
#include "object_server.hpp"
#include "service_parts.hpp"

#include <optional>

namespace eposp::device {

/// Resolves the address of an object command (maxon EPOS2 communication guide: NodeId 0 is the
/// device the link is plugged into, others the node on its CAN bus; the network-addressed
/// opcodes name 0 the controller, 1 its internal port, 2 its external port). A plain request
/// to the controller's own node-ID on its CAN port is local too. A device without CAN reaches
/// NodeId 0 only. The error is the dialect's wrong node.
ObjectServer::Resolved resolve_object_target(const ServiceParts& parts,
                                             const service::ObjectAddress& address);
/// The CAN port a frame command (NMT, CAN frame, LSS) of `network` goes to; null for the
/// controller itself, which has no bus of its own to send on.
NetworkPort* resolve_port(const ServiceParts& parts, std::optional<service::Network> network);

} // namespace eposp::device
