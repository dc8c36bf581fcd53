#pragma once

#include "eposp/can/port.hpp"

#include <functional>

namespace eposp::can {

/// A port that sends through another one while `open()` says so, and drops the frames
/// otherwise (reported as queued: the sender goes on as if its controller had taken them). A
/// node whose services must keep quiet for a while (LSS activate bit timing, CiA 305) hands them
/// this port. Received frames are not its business: the owner of the inner port dispatches them.
class GatedPort : public Port {
public:
    GatedPort(Port& inner, std::function<bool()> open);

    SendStatus send(const Frame& frame) override;
    std::size_t withdraw(const std::function<bool(const Frame&)>& which) override;
    ErrorState error_state() const override { return inner_.error_state(); }
    std::string_view name() const override { return inner_.name(); }

private:
    Port& inner_;
    std::function<bool()> open_;
};

} // namespace eposp::can
