#include "eposp/can/port_bridge.hpp"

namespace eposp::can {

PortBridge::PortBridge(Port& a, Port& b) : a_(a), b_(b) {
    a_.on_receive([this](const Frame& frame) { forward(frame, b_, a_to_b_); });
    b_.on_receive([this](const Frame& frame) { forward(frame, a_, b_to_a_); });
}

PortBridge::~PortBridge() {
    a_.on_receive(nullptr);
    b_.on_receive(nullptr);
}

void PortBridge::forward(const Frame& frame, Port& to, DirectionStatistics& statistics) {
    const SendStatus status = to.send(frame);
    if (status == SendStatus::Queued) {
        ++statistics.forwarded;
    } else {
        ++statistics.refused;
        statistics.last_refusal = status;
    }
}

} // namespace eposp::can
