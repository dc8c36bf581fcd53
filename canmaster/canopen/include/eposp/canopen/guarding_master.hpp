#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace eposp::canopen {

/// The master side of node guarding for one slave (CiA 301 7.2.8.3.2.1).
///
/// start() sends a remote frame on 0x700 + node-ID at once and then every guard time. A reply
/// is one data byte, the toggle bit (bit 7) and the slave's NMT state, and counts when it comes
/// before the next request with the toggle bit alternating; the first reply after start() or
/// after the slave's boot-up message (toggle 0 then) sets the phase. A reply with the wrong
/// toggle does not count (the listeners are told, and the phase follows the slave again). When
/// `life_time_factor` requests in a row (at least one) go without a reply that counts, the node
/// is lost: a node guarding event; the next reply that counts resolves it.
class GuardingMaster {
public:
    enum class Event : std::uint8_t {
        WrongToggle,  ///< a reply whose toggle bit did not alternate
        NodeLost,     ///< the node guarding event: the node life time passed without a reply
        NodeResolved, ///< a reply that counts after NodeLost
    };
    using EventListener = std::function<void(Event)>;
    using StateListener = std::function<void(NmtState)>;

    GuardingMaster(core::EventLoop& loop, can::Port& port, NodeId node);
    GuardingMaster(const GuardingMaster&) = delete;
    GuardingMaster& operator=(const GuardingMaster&) = delete;

    void start(core::Duration guard_time, std::uint8_t life_time_factor);
    void stop();
    void on_frame(const can::Frame& frame);

    /// The state of the last reply that counted; nullopt before one and while the node is lost.
    std::optional<NmtState> remote_state() const { return remote_state_; }
    void on_event(EventListener listener);
    void on_state_change(StateListener listener);

private:
    void poll();
    void report(NmtState state);
    void tell(Event event);

    core::EventLoop& loop_;
    can::Port& port_;
    NodeId node_;
    unsigned life_time_factor_ = 1;
    bool awaiting_reply_ = false;
    unsigned missed_ = 0;
    bool lost_ = false;
    std::optional<bool> expected_toggle_;
    std::optional<NmtState> remote_state_;
    core::ScopedTimer timer_;
    std::vector<EventListener> event_listeners_;
    std::vector<StateListener> state_listeners_;
};

} // namespace eposp::canopen
