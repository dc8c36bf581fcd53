#include "service_target.hpp"

#include "../network_port.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/epos_p_dictionary.hpp"

namespace eposp::device {
namespace {

ResolvedTarget node_on(NetworkPort& port, std::uint8_t node) {
    if (node == 0 || node > canopen::kMaxNodeId) {
        return {std::nullopt, service::error::kWrongNodeId};
    }
    return {ServiceTarget{&port, node}, service::error::kNone};
}

} // namespace

ServiceParts service_parts(EposP& device) {
    return ServiceParts{device.objects(), [&device](std::uint8_t port) -> NetworkPort& {
                            return device.network_port(port);
                        }};
}

ResolvedTarget resolve_object_target(const ServiceParts& parts,
                                     const service::ObjectAddress& address) {
    if (!address.network) {
        NetworkPort& can_port = parts.network_port(kExternalPort);
        if (address.node == 0 || address.node == can_port.own_node_id()) {
            return {ServiceTarget{}, service::error::kNone};
        }
        return node_on(can_port, address.node);
    }
    switch (*address.network) {
    case service::Network::Controller:
        return {ServiceTarget{}, service::error::kNone};
    case service::Network::InternalPort:
        return node_on(parts.network_port(kInternalPort), address.node);
    case service::Network::ExternalPort:
        return node_on(parts.network_port(kExternalPort), address.node);
    }
    return {std::nullopt, service::error::kWrongNodeId};
}

NetworkPort* resolve_port(const ServiceParts& parts, std::optional<service::Network> network) {
    if (!network || *network == service::Network::ExternalPort) {
        return &parts.network_port(kExternalPort);
    }
    if (*network == service::Network::InternalPort) {
        return &parts.network_port(kInternalPort);
    }
    return nullptr;
}

} // namespace eposp::device
