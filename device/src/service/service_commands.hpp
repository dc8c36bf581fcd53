#pragma once

#include "can_gateway.hpp"
#include "object_server.hpp"
#include "service_parts.hpp"

#include <optional>

namespace eposp::device {

/// Executes the requests of one service link (RS-232 or USB) on a device: decodes each request
/// frame and answers it (docs/service-interface.md, "Commands"). An opcode the device does not
/// serve (every one but the object commands on a device without CAN) is answered with the
/// dialect's "unknown command", parameters of the wrong length "length mismatch"; whether the
/// answer goes back (v1 does not answer the send commands) is the link's business.
class ServiceCommands {
public:
    using Done = std::function<void(service::Frame answer)>;

    ServiceCommands(core::EventLoop& loop, ServiceParts parts);

    /// Runs `request`; `done` gets the answer exactly once, possibly at once, unless the link
    /// is abandoned first.
    void execute(const service::Frame& request, Done done);
    /// The host went away: what it started ends, and no answer comes for it.
    void abandon();

    const ServiceParts& parts() const { return parts_; }

private:
    ServiceParts parts_;
    ObjectServer objects_;
    std::optional<CanGateway> gateway_; ///< on a device with CAN ports
};

} // namespace eposp::device
