#include "eposp/canmaster/canopen/sync_consumer.hpp"

#include "eposp/canmaster/canopen/cob_id.hpp"
#include "eposp/canmaster/canopen/sync_objects.hpp"

#include <chrono>

namespace eposp::canopen {

SyncConsumer::SyncConsumer(core::EventLoop& loop, ObjectDictionary& od, EmergencyCallback emergency)
    : loop_(loop), od_(od), emergency_(std::move(emergency)) {}

void SyncConsumer::on_frame(const can::Frame& frame) {
    // CiA 301 7.3.2.2: SYNC in pre-operational and operational only.
    if ((state_ != NmtState::PreOperational && state_ != NmtState::Operational) ||
        !matches(od_.get_as<std::uint32_t>(kCobIdSyncIndex, 0), frame)) {
        return;
    }
    const std::optional<std::size_t> expected = expected_length();
    if (expected ? frame.dlc != *expected : frame.dlc > 1) {
        if (expected && emergency_) {
            emergency_(kEmcySyncDataLength);
        }
        return;
    }
    SyncEvent event{.counter = std::nullopt, .window = window_length()};
    if (frame.dlc == 1) {
        event.counter = frame.data[0];
    }
    window_timer_.cancel();
    window_open_ = true;
    if (event.window != core::Duration::zero()) {
        window_timer_ =
            core::ScopedTimer(loop_, loop_.after(event.window, [this] { close_window(); }));
    }
    for (std::size_t i = 0; i < sync_listeners_.size(); ++i) {
        sync_listeners_[i](event);
    }
}

void SyncConsumer::set_nmt_state(NmtState state) {
    state_ = state;
    if (state == NmtState::Initialising || state == NmtState::Stopped) {
        window_timer_.cancel();
        window_open_ = false;
    }
}

void SyncConsumer::on_sync(SyncListener listener) {
    sync_listeners_.push_back(std::move(listener));
}

void SyncConsumer::on_window_closed(WindowListener listener) {
    window_listeners_.push_back(std::move(listener));
}

bool SyncConsumer::window_open() const {
    return window_open_ || window_length() == core::Duration::zero();
}

core::Duration SyncConsumer::window_length() const {
    if (od_.find(kSynchronousWindowLengthIndex, 0) == nullptr) {
        return core::Duration::zero();
    }
    return std::chrono::microseconds(od_.get_as<std::uint32_t>(kSynchronousWindowLengthIndex, 0));
}

// CiA 301 7.2.5.2.1: one byte with a counter overflow value, none without.
std::optional<std::size_t> SyncConsumer::expected_length() const {
    if (od_.find(kSyncCounterOverflowIndex, 0) == nullptr) {
        return std::nullopt;
    }
    return od_.get_as<std::uint8_t>(kSyncCounterOverflowIndex, 0) == 0 ? 0 : 1;
}

void SyncConsumer::close_window() {
    window_open_ = false;
    for (std::size_t i = 0; i < window_listeners_.size(); ++i) {
        window_listeners_[i]();
    }
}

} // namespace eposp::canopen
