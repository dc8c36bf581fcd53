#include "eposp/can/error_counters.hpp"

namespace eposp::can {
namespace {

constexpr unsigned kTransmitErrorStep = 8;
constexpr unsigned kReceiveCounterAfterPassive = 119;

} // namespace

ErrorState ErrorCounters::state() const {
    if (transmit_ > kBusOffAbove) {
        return ErrorState::BusOff;
    }
    if (transmit_ > kErrorPassiveAbove || receive_ > kErrorPassiveAbove) {
        return ErrorState::Passive;
    }
    if (transmit_ >= kErrorWarningFrom || receive_ >= kErrorWarningFrom) {
        return ErrorState::Warning;
    }
    return ErrorState::Active;
}

void ErrorCounters::transmit_error(bool ack_error) {
    if (ack_error && state() == ErrorState::Passive) {
        return;
    }
    transmit_ += kTransmitErrorStep;
}

void ErrorCounters::receive_error() {
    ++receive_;
}

void ErrorCounters::transmit_success() {
    if (transmit_ > 0) {
        --transmit_;
    }
}

void ErrorCounters::receive_success() {
    if (receive_ > kErrorPassiveAbove) {
        receive_ = kReceiveCounterAfterPassive;
    } else if (receive_ > 0) {
        --receive_;
    }
}

void ErrorCounters::reset() {
    transmit_ = 0;
    receive_ = 0;
}

void ErrorCounters::force(ErrorState state) {
    receive_ = 0;
    switch (state) {
    case ErrorState::Active:
        transmit_ = 0;
        break;
    case ErrorState::Warning:
        transmit_ = kErrorWarningFrom;
        break;
    case ErrorState::Passive:
        transmit_ = kErrorPassiveAbove + 1;
        break;
    case ErrorState::BusOff:
        transmit_ = kBusOffAbove + 1;
        break;
    }
}

} // namespace eposp::can
