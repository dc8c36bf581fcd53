#include "eposp/service/link.hpp"

namespace eposp::service {

void Link::deliver(std::span<const std::uint8_t> bytes) {
    statistics_.bytes_received += bytes.size();
    if (receive_handler_ && !bytes.empty()) {
        receive_handler_(bytes);
    }
}

void Link::report(LinkEvent event) {
    if (event.kind == LinkEvent::Kind::Closed) {
        if (closed_) {
            return; // told once
        }
        closed_ = true;
    } else {
        ++statistics_.hang_ups;
    }
    if (event_handler_) {
        event_handler_(event);
    }
}

} // namespace eposp::service
