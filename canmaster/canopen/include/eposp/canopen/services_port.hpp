#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/lss_slave.hpp"

#include <functional>

namespace eposp::canopen {

/// What a node's services send through: the node's port, closed while its LSS slave is silent
/// (CiA 305 activate bit timing), when a frame is dropped and reported as queued (the service
/// goes on as if its controller had taken it). The slave is asked by a plain call: every TPDO of
/// every node passes here. Received frames are not its business: the node dispatches them.
class ServicesPort final : public can::Port {
public:
    /// `inner` and `lss` must outlive the port.
    ServicesPort(can::Port& inner, const LssSlave& lss) : inner_(inner), lss_(lss) {}

    can::SendStatus send(const can::Frame& frame) override;
    std::size_t withdraw(const std::function<bool(const can::Frame&)>& which) override;
    can::ErrorState error_state() const override { return inner_.error_state(); }
    std::string_view name() const override { return inner_.name(); }

private:
    can::Port& inner_;
    const LssSlave& lss_;
};

} // namespace eposp::canopen
