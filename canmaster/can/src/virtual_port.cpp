#include "eposp/can/virtual_bus.hpp"
#include "virtual_bus_impl.hpp"

#include <algorithm>
#include <stdexcept>

namespace eposp::can {

VirtualPort::VirtualPort(VirtualBus& bus, std::string name, std::size_t tx_queue_capacity)
    : bus_(&bus), name_(std::move(name)),
      impl_(std::make_unique<Impl>(*this, bus.impl_->next_sequence++, tx_queue_capacity)) {}

VirtualPort::~VirtualPort() {
    if (bus_ != nullptr) {
        bus_->impl_->detach(*this);
    }
}

SendStatus VirtualPort::send(const Frame& frame) {
    if (bus_ == nullptr) {
        return SendStatus::Disconnected;
    }
    if (!frame.valid()) {
        return SendStatus::InvalidFrame;
    }
    if (impl_->counters.state() == ErrorState::BusOff) {
        return SendStatus::BusOff;
    }
    // A deque's size() walks its node map, its empty() compares two pointers: the queue is
    // usually empty when a frame comes.
    const bool was_empty = impl_->tx_queue.empty();
    if (was_empty ? impl_->tx_queue_capacity == 0
                  : impl_->tx_queue.size() >= impl_->tx_queue_capacity) {
        ++impl_->counts.tx_overflows;
        impl_->report_overflow(Overflow::Transmit, frame);
        return SendStatus::TxOverflow;
    }
    impl_->tx_queue.push_back(frame);
    if (was_empty) { // else the frame it offers stays the same
        bus_->impl_->refresh_queued(*impl_);
    }
    bus_->impl_->request_arbitration();
    return SendStatus::Queued;
}

std::size_t VirtualPort::withdraw(const std::function<bool(const Frame&)>& which) {
    if (bus_ == nullptr) {
        return 0;
    }
    std::deque<Frame>& queue = impl_->tx_queue;
    const std::optional<Transmission>& on_wire = bus_->impl_->current;
    const bool head_on_wire = on_wire && on_wire->sender == impl_.get() && on_wire->from_queue;
    const auto first = queue.begin() + (head_on_wire && !queue.empty() ? 1 : 0);
    const auto kept_end = std::remove_if(first, queue.end(), which);
    const auto withdrawn = static_cast<std::size_t>(queue.end() - kept_end);
    queue.erase(kept_end, queue.end());
    bus_->impl_->refresh_queued(*impl_);
    return withdrawn;
}

ErrorState VirtualPort::error_state() const {
    return impl_->counters.state();
}

PortStatistics VirtualPort::statistics() const {
    PortStatistics stats = impl_->counts;
    if (bus_ != nullptr) {
        stats.rx_frames += bus_->impl_->unvisited_receptions(*impl_);
    }
    stats.transmit_error_counter = impl_->counters.transmit();
    stats.receive_error_counter = impl_->counters.receive();
    stats.state = impl_->counters.state();
    return stats;
}

void VirtualPort::pause_receive(bool paused) {
    impl_->paused = paused;
    while (!impl_->paused && !impl_->rx_queue.empty()) {
        const Frame frame = impl_->rx_queue.front();
        impl_->rx_queue.pop_front();
        deliver(frame);
    }
    if (bus_ != nullptr) {
        bus_->impl_->refresh_attention(*impl_);
    }
}

void VirtualPort::filter_changed() {
    if (bus_ != nullptr) {
        bus_->impl_->index_filter(*impl_);
    }
}

void VirtualPort::on_overflow(OverflowHandler handler) {
    impl_->overflow_handler = std::move(handler);
}

void VirtualPort::recover() {
    if (bus_ != nullptr && impl_->counters.state() == ErrorState::BusOff && !impl_->recovering) {
        bus_->impl_->start_recovery(*impl_);
    }
}

void VirtualPort::force_error_state(ErrorState state) {
    const ErrorState before = impl_->counters.state();
    impl_->counters.force(state);
    if (bus_ != nullptr) {
        bus_->impl_->refresh_attention(*impl_);
        bus_->impl_->settle_state(*impl_, before);
    } else if (state != before) {
        notify_error_state(state);
    }
}

void VirtualPort::babble(const Frame& frame) {
    if (!frame.valid()) {
        throw std::invalid_argument("VirtualPort::babble: the frame is not valid");
    }
    impl_->babbled = frame;
    if (bus_ != nullptr) {
        bus_->impl_->refresh_queued(*impl_);
        bus_->impl_->request_arbitration();
    }
}

void VirtualPort::stop_babbling() {
    impl_->babbled.reset();
    if (bus_ != nullptr) {
        bus_->impl_->refresh_queued(*impl_);
    }
}

} // namespace eposp::can
