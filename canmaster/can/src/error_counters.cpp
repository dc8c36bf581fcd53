#include "eposp/can/error_counters.hpp"

namespace eposp::can {
namespace {

constexpr unsigned kTransmitErrorStep = 8;
constexpr unsigned kReceiveCounterAfterPassive = 119;

} // namespace

void ErrorCounters::update_state() {
    if (transmit_ > kBusOffAbove) {
        state_ = ErrorState::BusOff;
    } else if (transmit_ > kErrorPassiveAbove || receive_ > kErrorPassiveAbove) {
        state_ = ErrorState::Passive;
    } else if (transmit_ >= kErrorWarningFrom || receive_ >= kErrorWarningFrom) {
        state_ = ErrorState::Warning;
    } else {
        state_ = ErrorState::Active;
    }
}

void ErrorCounters::transmit_error(bool ack_error) {
    if (ack_error && state() == ErrorState::Passive) {
        return;
    }
    transmit_ += kTransmitErrorStep;
    update_state();
}

void ErrorCounters::receive_error() {
    ++receive_;
    update_state();
}

void ErrorCounters::transmit_success() {
    if (transmit_ > 0) {
        --transmit_;
        update_state();
    }
}

void ErrorCounters::count_down_receive() {
    if (receive_ > kErrorPassiveAbove) {
        receive_ = kReceiveCounterAfterPassive;
    } else {
        --receive_;
    }
    update_state();
}

void ErrorCounters::reset() {
    transmit_ = 0;
    receive_ = 0;
    update_state();
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
    update_state();
}

} // namespace eposp::can
