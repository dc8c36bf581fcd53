#pragma once

#include "eposp/can/port.hpp"

#include <cstdint>

namespace eposp::can {

/// Joins two buses through one port on each: every frame one port receives is sent on the
/// other, both ways. Attaches a SocketCAN interface to a virtual bus as one of its ports.
/// Neither port receives its own frames, so nothing circulates. The bridge takes over both
/// ports' receive handlers while it exists; both ports must outlive it.
class PortBridge {
public:
    struct DirectionStatistics {
        std::uint64_t forwarded = 0; ///< frames the other port accepted
        std::uint64_t refused = 0;   ///< frames it did not (queue full, bus-off, ...)
        SendStatus last_refusal = SendStatus::Queued;
    };

    PortBridge(Port& a, Port& b);
    ~PortBridge();
    PortBridge(const PortBridge&) = delete;
    PortBridge& operator=(const PortBridge&) = delete;

    const DirectionStatistics& a_to_b() const { return a_to_b_; }
    const DirectionStatistics& b_to_a() const { return b_to_a_; }

private:
    static void forward(const Frame& frame, Port& to, DirectionStatistics& statistics);

    Port& a_;
    Port& b_;
    DirectionStatistics a_to_b_;
    DirectionStatistics b_to_a_;
};

} // namespace eposp::can
