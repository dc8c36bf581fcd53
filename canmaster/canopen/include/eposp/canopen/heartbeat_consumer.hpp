#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/canopen/emergency.hpp"
#include "eposp/canopen/frame_router.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <vector>

namespace eposp::canopen {

inline constexpr std::uint16_t kConsumerHeartbeatTimeIndex = 0x1016;

/// One entry of 0x1016: bits 31..24 reserved (0) by CiA 301, the port code on the EPOS P
/// (FW spec 10.11); bits 23..16 the producer's node-ID; bits 15..0 the time in ms.
struct ConsumerHeartbeatEntry {
    std::uint8_t port_code = 0;
    NodeId node = 0;
    std::uint16_t time_ms = 0;

    static ConsumerHeartbeatEntry decode(std::uint32_t value);
    /// A time or a node-ID of 0, or a node-ID above 127, leaves the entry unused.
    bool used() const;
};

/// 0x1016 Consumer Heartbeat Time, an ARRAY of `entries` UNSIGNED32 (CiA 301 7.5.2, 1016h; EPOS2
/// FW spec 8.2.13: 2 entries; EPOS P FW spec 10.11: 128). A write that would make two used
/// entries watch the same node (and port) is refused with ParameterIncompatibility
/// (0x06040043), as CiA 301 says.
void add_heartbeat_consumer_objects(ObjectDictionary& od, std::uint8_t entries);
/// That rule on the entries of a 0x1016 `od` already has (e.g. from an EDS), where they have no
/// hook of their own (add_write_rule()).
void enforce_heartbeat_consumer_rules(ObjectDictionary& od);

/// The heartbeat consumer (CiA 301 7.2.8.3.2.2) for the used entries of 0x1016 whose port code
/// is this consumer's (0 on a CiA 301 device). Monitoring of a node starts with its first
/// heartbeat (EPOS2 FW spec 8.2.13); each one restarts its time. A node that stays silent for
/// its time is a heartbeat event: the listeners are told, an EMCY 0x8130 is raised, its state
/// becomes unknown, and monitoring waits for its next heartbeat, which ends the event (error
/// resolved). A received boot-up message is the heartbeat of state Initialising. Active in
/// pre-operational, operational and stopped; a changed entry starts again from waiting for the
/// first heartbeat, and a changed entry or an NMT reset ends its heartbeat event.
class HeartbeatConsumer {
public:
    using StateListener = std::function<void(NodeId node, NmtState state)>;
    using TimeoutListener = std::function<void(NodeId node)>;

    HeartbeatConsumer(core::EventLoop& loop, ObjectDictionary& od, EmergencyCallback emergency,
                      std::uint8_t port_code = 0);
    ~HeartbeatConsumer();
    HeartbeatConsumer(const HeartbeatConsumer&) = delete;
    HeartbeatConsumer& operator=(const HeartbeatConsumer&) = delete;

    void on_frame(const can::Frame& frame);
    /// Adds the identifiers of the frames on_frame() takes now (FrameRouter).
    void receive_keys(ReceiveKeys& keys) const;
    void set_nmt_state(NmtState state);

    /// The state a monitored node reported last; nullopt before its first heartbeat, after a
    /// timeout, and for nodes not monitored.
    std::optional<NmtState> remote_state(NodeId node) const;
    /// Told when a monitored node's state changes, its first heartbeat included.
    void on_state_change(StateListener listener);
    void on_timeout(TimeoutListener listener);
    /// Told when a heartbeat event has ended: the producer's heartbeat came again.
    void on_error_resolved(ErrorResolvedCallback resolved) { resolved_ = std::move(resolved); }

private:
    struct Monitor {
        std::uint8_t sub_index = 0;
        core::Duration time{};
        std::optional<NmtState> state;
        core::ScopedTimer timer;
        ErrorCondition lost{kEmcyLifeGuardOrHeartbeat};
    };

    void reload();
    void reload_entry(std::uint8_t sub_index);
    /// Stops monitoring the nodes `which` selects; their heartbeat events end.
    void forget(const std::function<bool(const Monitor&)>& which);
    void expire(NodeId node);

    core::EventLoop& loop_;
    ObjectDictionary& od_;
    EmergencyCallback emergency_;
    ErrorResolvedCallback resolved_;
    std::uint8_t port_code_;
    NmtState state_ = NmtState::Initialising;
    std::map<NodeId, Monitor> monitors_;
    std::vector<StateListener> state_listeners_;
    std::vector<TimeoutListener> timeout_listeners_;
    ObjectDictionary::ListenerId listener_;
};

} // namespace eposp::canopen
