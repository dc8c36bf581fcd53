#include "eposp/can/gated_port.hpp"

#include <utility>

namespace eposp::can {

GatedPort::GatedPort(Port& inner, std::function<bool()> open)
    : inner_(inner), open_(std::move(open)) {}

SendStatus GatedPort::send(const Frame& frame) {
    return open_() ? inner_.send(frame) : SendStatus::Queued;
}

std::size_t GatedPort::withdraw(const std::function<bool(const Frame&)>& which) {
    return inner_.withdraw(which);
}

} // namespace eposp::can
