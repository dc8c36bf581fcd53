#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/can/port.hpp"
#include "eposp/canopen/emergency.hpp"
#include "eposp/canopen/frame_router.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/rpdo.hpp"
#include "eposp/canopen/tpdo.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace eposp::canopen {

/// Every RPDO and TPDO whose objects a dictionary holds (add_pdo_objects()), as one service for
/// a node to compose: frames and NMT state changes go to all of them, SYNC and the end of its
/// window to the synchronous ones (a list kept as their communication parameters change). At a
/// SYNC the TPDOs sample before the RPDOs apply what they received, so a synchronous TPDO
/// reports the state of the cycle that ends.
class PdoService {
public:
    /// The PDOs numbered `first_number`, first_number + 1, ... that `od` holds: 1 for a node's
    /// PDOs, 257 for the EPOS P's internal ones (0x1500, 0x1900).
    PdoService(core::EventLoop& loop, can::Port& port, ObjectDictionary& od,
               EmergencyCallback emergency = {}, std::size_t first_number = 1);
    ~PdoService();
    PdoService(const PdoService&) = delete;
    PdoService& operator=(const PdoService&) = delete;

    void on_frame(const can::Frame& frame);
    /// Adds the identifiers of the frames on_frame() takes now (FrameRouter).
    void receive_keys(ReceiveKeys& keys) const;
    /// The SYNC consumer's notification; `counter` is 0 for a SYNC without counter.
    void on_sync(std::uint8_t counter);
    /// The synchronous window of the last SYNC closed (SyncConsumer::on_window_closed).
    void on_window_closed();
    void set_nmt_state(NmtState state);
    /// Re-reads every PDO's parameters (after ObjectDictionary::reset_to_defaults).
    void reload();
    /// Told when an error an RPDO raised has ended (Rpdo::on_error_resolved).
    void on_error_resolved(const ErrorResolvedCallback& resolved);

    std::size_t rpdo_count() const { return rpdos_.size(); }
    std::size_t tpdo_count() const { return tpdos_.size(); }
    /// The service's PDO `number`, 1-based (PDO first_number + number - 1 of the dictionary);
    /// out of range is a programming error (std::out_of_range).
    Rpdo& rpdo(std::size_t number);
    Tpdo& tpdo(std::size_t number);

private:
    /// After a PDO read its parameters again: which of them SYNC concerns now.
    void list_synchronous();

    ObjectDictionary& od_;
    std::vector<std::unique_ptr<Rpdo>> rpdos_;
    std::vector<std::unique_ptr<Tpdo>> tpdos_;
    std::vector<ObjectDictionary::ListenerId> listeners_;
    std::vector<Tpdo*> synchronous_tpdos_; ///< in number order, as are the RPDOs
    std::vector<Rpdo*> synchronous_rpdos_;
    bool window_closed_ = false; ///< since the window of the last SYNC closed
};

} // namespace eposp::canopen
