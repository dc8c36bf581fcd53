#include "eposp/canopen/guarding_master.hpp"

#include "eposp/canopen/nmt_protocol.hpp"

#include <algorithm>

namespace eposp::canopen {
namespace {

constexpr std::uint8_t kToggleBit = 0x80;
constexpr std::uint8_t kBootUp = 0x00;

} // namespace

GuardingMaster::GuardingMaster(core::EventLoop& loop, can::Port& port, NodeId node)
    : loop_(loop), port_(port), node_(node) {}

void GuardingMaster::start(core::Duration guard_time, std::uint8_t life_time_factor) {
    life_time_factor_ = std::max<unsigned>(life_time_factor, 1);
    awaiting_reply_ = false;
    missed_ = 0;
    lost_ = false;
    expected_toggle_.reset();
    poll();
    timer_ = core::ScopedTimer(loop_, loop_.every(guard_time, [this] { poll(); }));
}

void GuardingMaster::stop() {
    timer_.cancel();
    awaiting_reply_ = false;
}

void GuardingMaster::on_frame(const can::Frame& frame) {
    if (frame.remote || frame.extended || frame.error || frame.dlc != 1 ||
        frame.id != error_control_can_id(node_)) {
        return;
    }
    const std::uint8_t byte = frame.data[0];
    if (byte == kBootUp) {
        // CiA 301 7.2.8.3.2.1: the slave was reset, its next reply has toggle 0.
        expected_toggle_ = false;
        report(NmtState::Initialising);
        return;
    }
    const bool toggle = (byte & kToggleBit) != 0;
    const std::optional<NmtState> state =
        decode_nmt_state(static_cast<std::uint8_t>(byte & ~kToggleBit));
    if (!awaiting_reply_ || !state) {
        return; // not an answer to our request (a heartbeat, say)
    }
    const bool in_phase = !expected_toggle_ || *expected_toggle_ == toggle;
    expected_toggle_ = !toggle;
    if (!in_phase) {
        tell(Event::WrongToggle);
        return;
    }
    awaiting_reply_ = false;
    missed_ = 0;
    if (lost_) {
        lost_ = false;
        tell(Event::NodeResolved);
    }
    report(*state);
}

void GuardingMaster::on_event(EventListener listener) {
    event_listeners_.push_back(std::move(listener));
}

void GuardingMaster::on_state_change(StateListener listener) {
    state_listeners_.push_back(std::move(listener));
}

void GuardingMaster::poll() {
    if (awaiting_reply_ && ++missed_ >= life_time_factor_ && !lost_) {
        lost_ = true;
        remote_state_.reset();
        tell(Event::NodeLost);
    }
    port_.send(can::Frame::remote_frame(error_control_can_id(node_), 1));
    awaiting_reply_ = true;
}

void GuardingMaster::report(NmtState state) {
    if (remote_state_ == state) {
        return;
    }
    remote_state_ = state;
    for (std::size_t i = 0; i < state_listeners_.size(); ++i) {
        state_listeners_[i](state);
    }
}

void GuardingMaster::tell(Event event) {
    for (std::size_t i = 0; i < event_listeners_.size(); ++i) {
        event_listeners_[i](event);
    }
}

} // namespace eposp::canopen
