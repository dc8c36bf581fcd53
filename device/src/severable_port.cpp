#include "severable_port.hpp"

namespace eposp::device {

SeverablePort::SeverablePort(can::Port& inner) : inner_(inner) {
    inner_.on_receive([this](const can::Frame& frame) {
        if (!cut_) {
            deliver(frame);
        }
    });
    inner_.on_error_state([this](can::ErrorState state) { notify_error_state(state); });
}

can::SendStatus SeverablePort::send(const can::Frame& frame) {
    return cut_ ? can::SendStatus::Queued : inner_.send(frame);
}

std::size_t SeverablePort::withdraw(const std::function<bool(const can::Frame&)>& which) {
    return inner_.withdraw(which);
}

} // namespace eposp::device
