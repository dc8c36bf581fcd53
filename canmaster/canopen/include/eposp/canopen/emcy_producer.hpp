#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/event_loop.hpp"

#include <array>
#include <cstdint>
#include <deque>
#include <map>

namespace eposp::canopen {

inline constexpr std::uint16_t kCobIdEmcyIndex = 0x1014;
inline constexpr std::uint16_t kInhibitTimeEmcyIndex = 0x1015;

/// 0x1014 COB-ID EMCY (default 0x80 + node-ID; bit 31 invalid, bit 29 29-bit identifier) and,
/// when `inhibit_time` (an EPOS2 has no 0x1015), 0x1015 Inhibit Time EMCY (UNSIGNED16, 100 µs)
/// (CiA 301 7.5.2, 1014h/1015h; EPOS2 FW spec 8.2.12). A 0x1014 write that names a reserved
/// identifier (CiA 301 7.3.5), sets bits 11..28 of an 11-bit identifier, or changes the identifier
/// while the EMCY is valid is refused with InvalidValue (0x06090030).
void add_emcy_objects(ObjectDictionary& od, NodeId node_id, bool inhibit_time = true);
/// The 0x1014 rule of add_emcy_objects() on a 0x1014 `od` already has (e.g. from an EDS), where
/// it has no hook of its own (add_write_rule()).
void enforce_emcy_rules(ObjectDictionary& od);

/// The EMCY producer (CiA 301 7.2.7; EPOS2 FW spec 4.1), on the objects of add_emcy_objects()
/// and add_error_objects().
///
/// raise() is an error event: the error becomes active, its code goes to the error history
/// 0x1003, the error register 0x1001 becomes the OR of the active errors' bits and, while any
/// error is active, the generic error bit (CiA 301 7.5.2.2), and one EMCY is sent: error code
/// (little-endian), error register, five manufacturer-specific bytes. Raising an active error
/// again does nothing (one EMCY per error event). clear() ends an error: the register is updated
/// and an EMCY with code 0x0000 and the remaining register is sent; one that ends while the node
/// may not send (a reset, stopped) goes out when it enters pre-operational or operational.
/// EMCYs are sent in pre-operational and operational only (EPOS2 FW spec 7.3.5), not while 0x1014
/// is invalid, and at least the inhibit time 0x1015 apart: those due sooner wait in order (up to
/// kMaxPending; later ones are lost, the history and register keep them all). A controller that
/// is bus-off sends nothing: the EMCYs it refuses wait until controller_recovered(). One whose
/// transmit queue is full keeps them too and offers the first again every kQueueRetry, as a
/// stack's process loop does, so an error is reported once there is room (the EPOS2's own
/// 0x81FF "CAN transmit queue overflow" among them) rather than lost with the frames before it.
class EmcyProducer {
public:
    using ManufacturerData = std::array<std::uint8_t, 5>;
    static constexpr std::size_t kMaxPending = 16;
    static constexpr core::Duration kQueueRetry = std::chrono::milliseconds(1);

    EmcyProducer(core::EventLoop& loop, can::Port& port, ObjectDictionary& od,
                 GenericErrorBit generic_bit = GenericErrorBit::WithEveryError);
    EmcyProducer(const EmcyProducer&) = delete;
    EmcyProducer& operator=(const EmcyProducer&) = delete;

    /// `register_bits`: the error_register bits the device's table gives the code.
    void raise(std::uint16_t error_code, std::uint8_t register_bits, ManufacturerData data = {});
    void clear(std::uint16_t error_code, ManufacturerData data = {});
    /// Ends every active error with one EMCY 0x0000 (a fault reset).
    void clear_all(ManufacturerData data = {});
    bool active(std::uint16_t error_code) const { return active_.contains(error_code); }

    void set_nmt_state(NmtState state);
    /// The CAN controller left bus-off: the EMCYs it refused go out now.
    void controller_recovered() { send_pending(); }

private:
    std::uint8_t update_register();
    void emit(std::uint16_t error_code, std::uint8_t error_register, const ManufacturerData& data);
    void send_pending();

    core::EventLoop& loop_;
    can::Port& port_;
    ObjectDictionary& od_;
    ErrorHistory history_;
    NmtState state_ = NmtState::Initialising;
    std::map<std::uint16_t, std::uint8_t> active_; ///< error code -> its register bits
    std::deque<can::Frame> pending_;
    bool reset_unsent_ = false; ///< an error ended while no EMCY could be sent
    core::ScopedTimer inhibit_timer_;
    core::ScopedTimer queue_retry_timer_; ///< the transmit queue was full
};

} // namespace eposp::canopen
