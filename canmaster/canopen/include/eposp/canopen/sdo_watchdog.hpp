#pragma once

#include "eposp/core/event_loop.hpp"

#include <functional>

namespace eposp::canopen {

/// The timeout of one SDO transfer (CiA 301 7.2.4.3.17, abort code 0x05040000): it expires when
/// no progress was made for the timeout. Progress (kick) only moves a deadline; the loop's timer
/// is re-armed when it fires early, so a transfer costs one timer per timeout period instead of
/// one per frame.
class SdoWatchdog {
public:
    SdoWatchdog(core::EventLoop& loop, std::function<void()> on_expiry);

    /// Starts watching: expiry `timeout` after the last kick().
    void start(core::Duration timeout);
    void kick();
    void stop();
    bool running() const { return running_; }

private:
    void arm();
    void fire();

    core::EventLoop& loop_;
    std::function<void()> on_expiry_;
    core::Duration timeout_{};
    core::TimePoint deadline_{};
    bool running_ = false;
    core::ScopedTimer timer_;
};

} // namespace eposp::canopen
