#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/can/port.hpp"
#include "eposp/canopen/emergency.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/pdo_mapping.hpp"
#include "eposp/canopen/pdo_objects.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace eposp::canopen {

/// EPOS2 FW spec 4.2.20: a data frame with the COB-ID of one of our own TPDOs: another node
/// sends with it.
inline constexpr std::uint16_t kEmcyTransmitCobIdCollision = 0x8150;

/// One transmit PDO (CiA 301 7.2.2, transmission types of 7.5.2.37): packs the mapped objects
/// as the device reads them (ObjectDictionary::get) and sends them
/// - 0: at the SYNC after an event;
/// - 1..240: at every n-th SYNC, the first one when the SYNC counter equals the SYNC start
///   value if both are used, else the n-th SYNC;
/// - 252: sampled at every SYNC, sent on a remote request;
/// - 253: sampled and sent on a remote request;
/// - 254/255: on an event, at most once per inhibit time (a later event waits for its end).
/// Events are trigger(), a change of a mapped object that changes the PDO's data (the
/// dictionary's change listeners), a remote request (254/255) and the event timer (254/255,
/// restarted by every transmission). Becoming active in Operational is an event too, so that
/// consumers learn the initial values. Remote requests are answered only where the COB-ID
/// allows RTR. Works in NMT Operational only.
///
/// Synchronous window (CiA 301 7.5.2.8, 0x1007): once the window of a SYNC closed, a
/// synchronous PDO (types 0..240, 252) still waiting in the controller's transmit queue is taken
/// back (Port::withdraw), and the data sampled at that SYNC is no longer sent (a type 252 remote
/// request goes unanswered until the next SYNC).
class Tpdo {
public:
    /// TPDO `number` (1..512) of `od`, whose objects add_pdo_objects() made.
    Tpdo(core::EventLoop& loop, can::Port& port, ObjectDictionary& od, std::size_t number,
         EmergencyCallback emergency = {});
    ~Tpdo();
    Tpdo(const Tpdo&) = delete;
    Tpdo& operator=(const Tpdo&) = delete;

    /// Every frame the node receives: remote requests for this TPDO, and collisions.
    void on_frame(const can::Frame& frame);
    /// The SYNC consumer's notification; `counter` is 0 for a SYNC without counter.
    void on_sync(std::uint8_t counter);
    /// The synchronous window of the last SYNC closed (SyncConsumer::on_window_closed).
    void on_window_closed();
    void set_nmt_state(NmtState state);
    /// An application event (transmission types 0, 254, 255).
    void trigger();
    /// Reads the parameters from the dictionary again (see Rpdo::reload).
    void reload();

    std::size_t number() const { return number_; }
    /// Valid with a usable, non-empty mapping (in whatever NMT state).
    bool active() const { return active_; }
    /// The COB-ID as last read, valid or not.
    PdoCobId cob_id() const { return comm_.cob_id; }
    /// Transmission types 0..240 and 252, the only ones SYNC and its window concern.
    bool synchronous() const {
        return comm_.transmission_type <= kSyncCyclicMax ||
               comm_.transmission_type == kRtrSynchronous;
    }

private:
    bool running() const { return active_ && operational_; }
    bool event_driven() const;
    /// Starts or stops after a change of validity or NMT state.
    void follow_running(bool was_running);
    void start();
    void stop();
    void watch_mapped_objects();
    void request(bool forced);
    void send_event_if_due();
    void on_cyclic_sync(std::uint8_t counter);
    void on_remote_request();
    void transmit(const PdoPayload& payload);
    void restart_event_timer();

    core::EventLoop& loop_;
    can::Port& port_;
    ObjectDictionary& od_;
    std::size_t number_;
    EmergencyCallback emergency_;
    std::vector<ObjectDictionary::ListenerId> config_listeners_;
    std::vector<ObjectDictionary::ListenerId> data_listeners_;
    PdoCommunication comm_;
    PdoMapping mapping_;
    bool active_ = false;
    bool operational_ = false;

    // Events: a forced one sends whatever the data; a change only if the data differ from the
    // last transmission.
    bool forced_pending_ = false;
    bool change_pending_ = false;
    std::optional<PdoPayload> last_payload_;
    std::optional<core::TimePoint> last_transmission_;
    core::ScopedTimer inhibit_timer_;
    core::ScopedTimer event_timer_;

    std::uint8_t syncs_to_go_ = 0;      ///< cyclic types; 0 until the first transmission is due
    std::optional<PdoPayload> sampled_; ///< type 252: the data of the last SYNC
};

} // namespace eposp::canopen
