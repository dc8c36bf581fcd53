#pragma once

#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/service/commands.hpp"

#include <cstdint>
#include <functional>
#include <optional>

namespace eposp::device {

class EposP;
class NetworkPort;

/// What a request of the service interface addresses: the controller's own dictionary, or a
/// node on one of its CAN ports (the gateway).
struct ServiceTarget {
    NetworkPort* port = nullptr; ///< null: the controller itself
    canopen::NodeId node = 0;
};

/// The controller's parts that the service interface reaches.
struct ServiceParts {
    canopen::ObjectDictionary& objects;
    /// Port 1 (internal) or 2 (external, the CAN port of the plain opcodes).
    std::function<NetworkPort&(std::uint8_t port)> network_port;
};

/// The parts of `device`.
ServiceParts service_parts(EposP& device);

/// Resolves the address of a request (maxon EPOS2 communication guide: NodeId 0 is the device
/// the link is plugged into, others the node on its CAN bus; the network-addressed opcodes name
/// 0 the controller, 1 its internal port, 2 its external port). A plain request to the
/// controller's own node-ID on its CAN port is local too. The error is kWrongNodeId.
struct ResolvedTarget {
    std::optional<ServiceTarget> target;
    std::uint32_t error = service::error::kNone;
};
ResolvedTarget resolve_object_target(const ServiceParts& parts,
                                     const service::ObjectAddress& address);
/// The CAN port a frame command (NMT, CAN frame, LSS) of `network` goes to; null for the
/// controller itself, which has no bus of its own to send on.
NetworkPort* resolve_port(const ServiceParts& parts, std::optional<service::Network> network);

} // namespace eposp::device
