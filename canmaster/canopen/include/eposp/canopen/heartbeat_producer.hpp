#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>

namespace eposp::canopen {

inline constexpr std::uint16_t kProducerHeartbeatTimeIndex = 0x1017;

/// 0x1017 Producer Heartbeat Time, UNSIGNED16 ms, 0 = off (CiA 301 7.5.2, 1017h; EPOS2 FW spec
/// 8.2.14).
void add_heartbeat_producer_object(ObjectDictionary& od);

/// The heartbeat producer (CiA 301 7.2.8.3.2.2): every 0x1017 ms, a frame 0x700 + node-ID with
/// the NMT state, in pre-operational, operational and stopped. The boot-up message counts as
/// the first heartbeat, so the next one follows one period after it. A new 0x1017 takes effect
/// at once: the next heartbeat follows one new period after the write; 0 stops the heartbeat.
class HeartbeatProducer {
public:
    HeartbeatProducer(core::EventLoop& loop, can::Port& port, ObjectDictionary& od, NodeId node_id);
    ~HeartbeatProducer();
    HeartbeatProducer(const HeartbeatProducer&) = delete;
    HeartbeatProducer& operator=(const HeartbeatProducer&) = delete;

    void set_nmt_state(NmtState state);
    /// A node-ID LSS configured, at the node's reset communication (CiA 305).
    void set_node_id(NodeId node_id) { node_id_ = node_id; }
    bool producing() const { return timer_.pending(); }

private:
    void restart();
    void send();

    core::EventLoop& loop_;
    can::Port& port_;
    ObjectDictionary& od_;
    NodeId node_id_;
    NmtState state_ = NmtState::Initialising;
    ObjectDictionary::ListenerId listener_;
    core::ScopedTimer timer_;
};

} // namespace eposp::canopen
