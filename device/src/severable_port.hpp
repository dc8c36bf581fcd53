#pragma once

#include "eposp/can/port.hpp"

namespace eposp::device {

/// A simulated node's cable to its bus, which fault injection can cut as if it broke at the
/// node's connector: while cut, what the node sends is lost (the node is told Queued, as a silent
/// LSS slave's canopen::ServicesPort tells it, and goes on as if its controller had sent it) and
/// it hears nothing. Its error state is the inner port's. The node is handed this port instead
/// of the bus's.
class SeverablePort : public can::Port {
public:
    /// Takes over `inner`'s receive and error-state handlers.
    explicit SeverablePort(can::Port& inner);

    can::SendStatus send(const can::Frame& frame) override;
    std::size_t withdraw(const std::function<bool(const can::Frame&)>& which) override;
    can::ErrorState error_state() const override { return inner_.error_state(); }
    std::string_view name() const override { return inner_.name(); }

    void set_cut(bool cut) { cut_ = cut; }
    bool cut() const { return cut_; }

private:
    can::Port& inner_;
    bool cut_ = false;
};

} // namespace eposp::device
