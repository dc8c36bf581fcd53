#include "eposp/canopen/services_port.hpp"

namespace eposp::canopen {

can::SendStatus ServicesPort::send(const can::Frame& frame) {
    return lss_.silent() ? can::SendStatus::Queued : inner_.send(frame);
}

std::size_t ServicesPort::withdraw(const std::function<bool(const can::Frame&)>& which) {
    return inner_.withdraw(which);
}

} // namespace eposp::canopen
