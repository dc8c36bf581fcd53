#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/canopen/emergency.hpp"
#include "eposp/canopen/frame_router.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace eposp::canopen {

class PdoService;

/// One SYNC as the consumer's listeners get it.
struct SyncEvent {
    std::optional<std::uint8_t> counter; ///< present when the SYNC carries a counter
    /// 0x1007: how long after this SYNC synchronous PDOs may still go out (CiA 301 7.5.2, 1007h);
    /// zero when there is no window.
    core::Duration window{};
};

/// The SYNC consumer (CiA 301 7.2.5), on the objects of add_sync_objects(): it takes the frames
/// with 0x1005's identifier in pre-operational and operational and tells its listeners of each
/// SYNC with its counter and the synchronous window length. The window (0x1007, when the device
/// has it and it is non-zero) opens with every SYNC and closes after its length: the window
/// listeners are told then, and window_open() says whether synchronous PDOs may still be sent.
/// When the device has 0x1019, a SYNC whose length does not match it (one byte with a counter,
/// none without) is ignored and raises EMCY 0x8240 (CiA 301 7.2.7.1), which the next SYNC of
/// the right length or an NMT reset ends.
class SyncConsumer {
public:
    using SyncListener = std::function<void(const SyncEvent&)>;
    using WindowListener = std::function<void()>;

    SyncConsumer(core::EventLoop& loop, ObjectDictionary& od, EmergencyCallback emergency);
    ~SyncConsumer();
    SyncConsumer(const SyncConsumer&) = delete;
    SyncConsumer& operator=(const SyncConsumer&) = delete;

    /// A frame from the bus, or a SYNC this node produced itself (SyncProducer::on_sent).
    void on_frame(const can::Frame& frame);
    /// Adds the identifiers of the frames on_frame() takes now (FrameRouter).
    void receive_keys(ReceiveKeys& keys) const;
    void set_nmt_state(NmtState state);

    /// The PDOs this consumer synchronises: told of every SYNC (the counter, 0 without one) and
    /// of the end of its window before the listeners, by a plain call (every SYNC reaches every
    /// node's PDOs, and a listener's std::function would add a hop). `pdos` must outlive it.
    void synchronise(PdoService& pdos) { pdos_ = &pdos; }
    void on_sync(SyncListener listener);
    void on_window_closed(WindowListener listener);
    /// Told when the SYNC length error has ended.
    void on_error_resolved(ErrorResolvedCallback resolved) { resolved_ = std::move(resolved); }
    /// True from a SYNC until its window closes; always true without a window.
    bool window_open() const;

private:
    void read_parameters();
    void close_window();

    core::EventLoop& loop_;
    ObjectDictionary& od_;
    EmergencyCallback emergency_;
    ErrorResolvedCallback resolved_;
    ErrorCondition wrong_length_{kEmcySyncDataLength};
    /// 0x1005, 0x1007 and 0x1019 as last read: every frame on the bus passes on_frame(), so
    /// they are read when written and when the NMT state changes (a reset restores them
    /// without telling listeners), not per frame.
    std::optional<std::uint32_t> cob_id_; ///< none without 0x1005
    core::Duration window_length_{};
    std::optional<std::size_t> expected_length_;
    std::vector<ObjectDictionary::ListenerId> od_listeners_;
    NmtState state_ = NmtState::Initialising;
    bool window_open_ = false;
    core::ScopedTimer window_timer_;
    PdoService* pdos_ = nullptr;
    std::vector<SyncListener> sync_listeners_;
    std::vector<WindowListener> window_listeners_;
};

} // namespace eposp::canopen
