#pragma once

#include "eposp/can/port.hpp"
#include "eposp/core/event_loop.hpp"

#include <deque>

namespace eposp::canopen {

/// Sends frames through a port in order, none lost to a full transmit queue: a frame the port
/// has no room for waits here, with those after it, and is offered again after a delay (a
/// controller has no "sent" event to wait for). The SDO client's transfers with up to 127
/// servers share one port, so their requests can outnumber its queue.
class SdoTransmitQueue {
public:
    SdoTransmitQueue(core::EventLoop& loop, can::Port& port, core::Duration retry_delay);

    void send(const can::Frame& frame);
    /// Frames waiting for room in the port's queue.
    std::size_t backlog() const { return backlog_.size(); }

private:
    void drain();

    core::EventLoop& loop_;
    can::Port& port_;
    core::Duration retry_delay_;
    std::deque<can::Frame> backlog_;
    core::ScopedTimer retry_;
};

} // namespace eposp::canopen
