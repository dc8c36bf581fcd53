#include "eposp/canopen/sdo_watchdog.hpp"

namespace eposp::canopen {

SdoWatchdog::SdoWatchdog(core::EventLoop& loop, std::function<void()> on_expiry)
    : loop_(loop), on_expiry_(std::move(on_expiry)) {}

void SdoWatchdog::start(core::Duration timeout) {
    timeout_ = timeout;
    running_ = true;
    kick();
}

void SdoWatchdog::kick() {
    if (!running_) {
        return;
    }
    deadline_ = loop_.now() + timeout_;
    if (!timer_.pending()) {
        arm();
    }
}

void SdoWatchdog::stop() {
    running_ = false;
    timer_.cancel();
}

void SdoWatchdog::arm() {
    timer_ = core::ScopedTimer(loop_, loop_.at(deadline_, [this] { fire(); }));
}

void SdoWatchdog::fire() {
    if (!running_) {
        return;
    }
    if (loop_.now() < deadline_) {
        arm();
        return;
    }
    running_ = false;
    on_expiry_();
}

} // namespace eposp::canopen
