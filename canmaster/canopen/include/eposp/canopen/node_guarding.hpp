#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/emergency.hpp"
#include "eposp/canopen/frame_router.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace eposp::canopen {

inline constexpr std::uint16_t kGuardTimeIndex = 0x100C;
inline constexpr std::uint16_t kLifeTimeFactorIndex = 0x100D;

/// 0x100C Guard Time (UNSIGNED16 ms) and 0x100D Life Time Factor (UNSIGNED8), both 0 by default
/// (CiA 301 7.5.2, 100Ch/100Dh; EPOS2 FW spec 8.2.6/8.2.7).
void add_node_guarding_objects(ObjectDictionary& od);

/// The slave side of node guarding and life guarding (CiA 301 7.2.8.3.2.1).
///
/// A remote frame on 0x700 + node-ID is answered with one byte: the toggle bit (bit 7) and the
/// NMT state. The first answer after the boot-up has toggle 0, and each answer flips it; only a
/// reset brings it back to 0. Life guarding starts with the first guarding request when guard
/// time and life time factor are both non-zero: a life time (their product) without a request
/// is a life guarding event, told to the listeners (occurred), with an EMCY 0x8130; the next
/// request resolves it (listeners told again, error resolved), and so does an NMT reset. A node
/// must not use guarding and heartbeat at once: while 0x1017 is non-zero it answers no guarding
/// request and life guarding is off (EPOS2 FW spec 8.2.6). Active in pre-operational, operational
/// and stopped.
class NodeGuarding {
public:
    /// `occurred` true: the life time elapsed without a request; false: requests came again.
    using LifeGuardingListener = std::function<void(bool occurred)>;

    NodeGuarding(core::EventLoop& loop, can::Port& port, ObjectDictionary& od, NodeId node_id,
                 EmergencyCallback emergency);
    ~NodeGuarding();
    NodeGuarding(const NodeGuarding&) = delete;
    NodeGuarding& operator=(const NodeGuarding&) = delete;

    void on_frame(const can::Frame& frame);
    /// Adds the identifiers of the frames on_frame() takes now (FrameRouter).
    void receive_keys(ReceiveKeys& keys) const;
    void set_nmt_state(NmtState state);
    /// A node-ID LSS configured, at the node's reset communication (CiA 305).
    void set_node_id(NodeId node_id) { node_id_ = node_id; }
    void on_life_guarding_event(LifeGuardingListener listener);
    /// Told when a life guarding event has ended.
    void on_error_resolved(ErrorResolvedCallback resolved) { resolved_ = std::move(resolved); }

private:
    bool heartbeat_in_use() const;
    core::Duration life_time() const;
    void rearm();
    void expire();
    void tell(bool occurred);

    core::EventLoop& loop_;
    can::Port& port_;
    ObjectDictionary& od_;
    NodeId node_id_;
    EmergencyCallback emergency_;
    ErrorResolvedCallback resolved_;
    /// A life guarding event occurred and is not resolved.
    ErrorCondition life_guarding_event_{kEmcyLifeGuardOrHeartbeat};
    NmtState state_ = NmtState::Initialising;
    bool toggle_ = false;
    bool guarded_ = false; ///< a request came since the boot-up: life guarding runs
    core::ScopedTimer life_timer_;
    std::vector<LifeGuardingListener> listeners_;
    std::vector<ObjectDictionary::ListenerId> od_listeners_;
};

} // namespace eposp::canopen
