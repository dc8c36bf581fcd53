#pragma once

#include "can_gateway.hpp"
#include "object_transfer.hpp"

namespace eposp::device {

/// Executes the requests of one service link (RS-232 or USB) on the controller: decodes each
/// request frame and answers it (docs/service-interface.md, "Commands"). An unknown opcode is
/// answered "illegal command", parameters of the wrong length "length mismatch"; whether the
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

private:
    ServiceParts parts_;
    ObjectTransfer objects_;
    CanGateway gateway_;
};

} // namespace eposp::device
