#include "eposp/can/port.hpp"

namespace eposp::can {

std::size_t Port::withdraw(const std::function<bool(const Frame&)>& /*which*/) {
    return 0;
}

std::string_view to_string(ErrorState state) {
    switch (state) {
    case ErrorState::Active:
        return "error-active";
    case ErrorState::Warning:
        return "error-warning";
    case ErrorState::Passive:
        return "error-passive";
    case ErrorState::BusOff:
        return "bus-off";
    }
    return "unknown";
}

std::string_view to_string(SendStatus status) {
    switch (status) {
    case SendStatus::Queued:
        return "queued";
    case SendStatus::TxOverflow:
        return "transmit queue full";
    case SendStatus::BusOff:
        return "bus-off";
    case SendStatus::InvalidFrame:
        return "invalid frame";
    case SendStatus::Disconnected:
        return "not connected to a bus";
    }
    return "unknown";
}

} // namespace eposp::can
