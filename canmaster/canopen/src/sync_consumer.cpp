#include "eposp/canopen/sync_consumer.hpp"

#include "eposp/canopen/cob_id.hpp"
#include "eposp/canopen/pdo_service.hpp"
#include "eposp/canopen/sync_objects.hpp"

#include <chrono>

namespace eposp::canopen {

SyncConsumer::SyncConsumer(core::EventLoop& loop, ObjectDictionary& od, EmergencyCallback emergency)
    : loop_(loop), od_(od), emergency_(std::move(emergency)) {
    for (const std::uint16_t index :
         {kCobIdSyncIndex, kSynchronousWindowLengthIndex, kSyncCounterOverflowIndex}) {
        od_listeners_.push_back(od.on_change(index, [this](auto, auto) { read_parameters(); }));
    }
    read_parameters();
}

SyncConsumer::~SyncConsumer() {
    for (const auto id : od_listeners_) {
        od_.remove_listener(id);
    }
}

void SyncConsumer::receive_keys(ReceiveKeys& keys) const {
    if (cob_id_) {
        keys.push_back(receive_key(*cob_id_));
    }
}

void SyncConsumer::on_frame(const can::Frame& frame) {
    // CiA 301 7.3.2.2: SYNC in pre-operational and operational only.
    if ((state_ != NmtState::PreOperational && state_ != NmtState::Operational) || !cob_id_ ||
        !matches(*cob_id_, frame)) {
        return;
    }
    const std::optional<std::size_t> expected = expected_length_;
    const bool wrong_length = expected ? frame.dlc != *expected : frame.dlc > 1;
    wrong_length_.set(wrong_length && expected.has_value(), emergency_, resolved_);
    if (wrong_length) {
        return;
    }
    window_timer_.cancel();
    window_open_ = true;
    const core::Duration window = window_length_;
    if (window != core::Duration::zero()) {
        window_timer_ = core::ScopedTimer(loop_, loop_.after(window, [this] { close_window(); }));
    }
    const std::optional<std::uint8_t> counter =
        frame.dlc == 1 ? std::optional<std::uint8_t>(frame.data[0]) : std::nullopt;
    if (pdos_ != nullptr) {
        pdos_->on_sync(counter.value_or(0));
    }
    if (sync_listeners_.empty()) {
        return;
    }
    const SyncEvent event{.counter = counter, .window = window};
    for (std::size_t i = 0; i < sync_listeners_.size(); ++i) {
        sync_listeners_[i](event);
    }
}

void SyncConsumer::set_nmt_state(NmtState state) {
    state_ = state;
    read_parameters();
    if (state == NmtState::Initialising || state == NmtState::Stopped) {
        window_timer_.cancel();
        window_open_ = false;
    }
    if (state == NmtState::Initialising) {
        wrong_length_.set(false, emergency_, resolved_);
    }
}

void SyncConsumer::on_sync(SyncListener listener) {
    sync_listeners_.push_back(std::move(listener));
}

void SyncConsumer::on_window_closed(WindowListener listener) {
    window_listeners_.push_back(std::move(listener));
}

bool SyncConsumer::window_open() const {
    return window_open_ || window_length_ == core::Duration::zero();
}

// CiA 301 7.2.5.2.1: one byte with a counter overflow value, none without (0x1019 absent: any
// length up to one byte). Without 0x1007 there is no window.
void SyncConsumer::read_parameters() {
    cob_id_.reset();
    if (od_.find(kCobIdSyncIndex, 0) != nullptr) {
        cob_id_ = od_.get_as<std::uint32_t>(kCobIdSyncIndex, 0);
    }
    window_length_ = od_.find(kSynchronousWindowLengthIndex, 0) == nullptr
                         ? core::Duration::zero()
                         : std::chrono::microseconds(
                               od_.get_as<std::uint32_t>(kSynchronousWindowLengthIndex, 0));
    expected_length_.reset();
    if (od_.find(kSyncCounterOverflowIndex, 0) != nullptr) {
        expected_length_ = od_.get_as<std::uint8_t>(kSyncCounterOverflowIndex, 0) == 0 ? 0 : 1;
    }
}

void SyncConsumer::close_window() {
    window_open_ = false;
    if (pdos_ != nullptr) {
        pdos_->on_window_closed();
    }
    for (std::size_t i = 0; i < window_listeners_.size(); ++i) {
        window_listeners_[i]();
    }
}

} // namespace eposp::canopen
