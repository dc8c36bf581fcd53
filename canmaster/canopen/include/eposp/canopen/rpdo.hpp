#pragma once

#include "eposp/can/frame.hpp"
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
#include <span>
#include <vector>

namespace eposp::canopen {

// CiA 301 7.2.7.1 table 21 (EPOS2 FW spec 4.2.21): emergency error codes of a received PDO.
inline constexpr std::uint16_t kEmcyPdoLengthError = 0x8210;    ///< shorter than mapped
inline constexpr std::uint16_t kEmcyPdoLengthExceeded = 0x8220; ///< longer than mapped
inline constexpr std::uint16_t kEmcyRpdoTimeout = 0x8250;       ///< deadline missed

/// One receive PDO (CiA 301 7.2.2): takes the frames with its COB-ID and stores their data into
/// the mapped objects with the device's own access (ObjectDictionary::set), at once for the
/// event-driven transmission types 254/255, at the next SYNC for the synchronous types
/// 0..240. It works in NMT Operational only and follows its communication and mapping objects
/// as they change.
///
/// A frame shorter than the mapping is not processed and raises EMCY 0x8210; a longer one is
/// processed with its first bytes and raises EMCY 0x8220 (CiA 301 7.2.2). Each error lasts
/// until the next frame of the right length.
///
/// Deadline monitoring (CiA 301 7.5.2.35, sub-index 5): with a non-zero event timer, each RPDO
/// received starts it again; when it runs out before the next one, EMCY 0x8250 is raised, and
/// the next RPDO of the right length ends it. It runs from the first RPDO received in
/// Operational.
///
/// A change of the RPDO's parameters and an NMT reset (reload()) end its errors.
///
/// Synchronous window (CiA 301 7.5.2.8, 0x1007): synchronous RPDOs received after the window
/// of a SYNC closed are discarded until the next SYNC.
class Rpdo {
public:
    /// RPDO `number` (1..512) of `od`, whose objects add_pdo_objects() made.
    Rpdo(core::EventLoop& loop, ObjectDictionary& od, std::size_t number,
         EmergencyCallback emergency);
    ~Rpdo();
    Rpdo(const Rpdo&) = delete;
    Rpdo& operator=(const Rpdo&) = delete;

    /// Every frame the node receives; frames that are not this RPDO's are ignored.
    void on_frame(const can::Frame& frame);
    /// The SYNC consumer's notification; `counter` is 0 for a SYNC without counter.
    void on_sync(std::uint8_t counter);
    /// The synchronous window of the last SYNC closed (SyncConsumer::on_window_closed).
    void on_window_closed();
    /// Whether the window of the last SYNC has closed, for an RPDO that was not told of the
    /// SYNCs while it was not synchronous (PdoService tells only the synchronous ones).
    void set_window_closed(bool closed) { window_closed_ = closed; }
    void set_nmt_state(NmtState state);
    /// Reads the parameters from the dictionary again: for changes it was not told of
    /// (ObjectDictionary::reset_to_defaults tells no listener).
    void reload();

    /// Told when an error this RPDO raised has ended.
    void on_error_resolved(ErrorResolvedCallback resolved) { resolved_ = std::move(resolved); }

    /// Told each time received data has been stored into the mapped objects (at once, or at
    /// the SYNC for a synchronous RPDO).
    void on_applied(std::function<void()> listener) { applied_.push_back(std::move(listener)); }

    std::size_t number() const { return number_; }
    /// Valid with a usable, non-empty mapping (in whatever NMT state).
    bool active() const { return active_; }
    /// The COB-ID as last read, valid or not.
    PdoCobId cob_id() const { return comm_.cob_id; }
    /// Transmission types 0..240: applied at the SYNC; the others ignore SYNC.
    bool synchronous() const { return comm_.transmission_type <= kSyncCyclicMax; }

private:
    bool accepts(const can::Frame& frame) const;
    void restart_deadline();
    /// The errors of the last frame received, or none.
    void report_frame_errors(bool too_short, bool too_long, bool deadline_missed);
    void apply(std::span<const std::uint8_t> data);

    core::EventLoop& loop_;
    ObjectDictionary& od_;
    std::size_t number_;
    EmergencyCallback emergency_;
    ErrorResolvedCallback resolved_;
    ErrorCondition too_short_{kEmcyPdoLengthError};
    ErrorCondition too_long_{kEmcyPdoLengthExceeded};
    ErrorCondition deadline_missed_{kEmcyRpdoTimeout};
    std::vector<ObjectDictionary::ListenerId> listeners_;
    std::vector<std::function<void()>> applied_;
    PdoCommunication comm_;
    PdoMapping mapping_;
    bool active_ = false;
    bool operational_ = false;
    std::optional<Bytes> pending_; ///< synchronous data waiting for the next SYNC
    bool window_closed_ = false;   ///< since the window of the last SYNC closed
    core::ScopedTimer deadline_;
};

} // namespace eposp::canopen
