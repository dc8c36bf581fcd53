#include "service_target.hpp"

#include "../network_port.hpp"
#include "dictionary_access.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "gateway_access.hpp"

namespace eposp::device {
namespace {

ObjectServer::Resolved own_objects(const ServiceParts& parts) {
    return {std::make_shared<DictionaryAccess>(parts.objects), service::error::kNone};
}

ObjectServer::Resolved node_on(const ServiceParts& parts, NetworkPort& port, std::uint8_t node) {
    if (node == 0 || node > canopen::kMaxNodeId) {
        return {nullptr, parts.dialect.wrong_node};
    }
    return {std::make_shared<GatewayAccess>(port, node), service::error::kNone};
}

} // namespace

ObjectServer::Resolved resolve_object_target(const ServiceParts& parts,
                                             const service::ObjectAddress& address) {
    if (!parts.network_port) {
        const bool itself = address.node == 0 &&
                            (!address.network || *address.network == service::Network::Controller);
        return itself ? own_objects(parts)
                      : ObjectServer::Resolved{nullptr, parts.dialect.wrong_node};
    }
    if (!address.network) {
        NetworkPort& can_port = parts.network_port(kExternalPort);
        if (address.node == 0 || address.node == can_port.own_node_id()) {
            return own_objects(parts);
        }
        return node_on(parts, can_port, address.node);
    }
    switch (*address.network) {
    case service::Network::Controller:
        return own_objects(parts);
    case service::Network::InternalPort:
        return node_on(parts, parts.network_port(kInternalPort), address.node);
    case service::Network::ExternalPort:
        return node_on(parts, parts.network_port(kExternalPort), address.node);
    }
    return {nullptr, parts.dialect.wrong_node};
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
