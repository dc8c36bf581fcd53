#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <functional>
#include <set>
#include <vector>

namespace eposp::canopen {

class ObjectDictionary;

/// The LSS address of a node: its identity object 0x1018 sub 1..4 (EPOS2 FW spec 7.4).
LssAddress lss_address_from_dictionary(const ObjectDictionary& dictionary);

/// What store configuration reports (EPOS2 FW spec 7.4.2.6): the error code of its response.
enum class LssStoreResult : std::uint8_t {
    Stored = kLssSuccess,
    NotSupported = kLssStoreNotSupported,
    StorageAccessError = kLssStorageAccessError,
};

/// The configuration LSS stores: the pending node-ID and bit rate (bit/s).
struct LssConfiguration {
    NodeId node_id = kLssUnconfiguredNodeId;
    std::uint32_t bit_rate = 0;
    friend bool operator==(const LssConfiguration&, const LssConfiguration&) = default;
};

struct LssSlaveConfig {
    /// The node-ID and bit rate the device started with (its stored configuration): they are
    /// both the active and the pending values until LSS changes the pending ones.
    LssConfiguration initial;
    /// EPOS2 FW spec 7.4: LSS is only accessible in NMT state Stopped. A device that has no
    /// node-ID cannot be stopped and takes LSS commands in any state.
    bool only_when_nmt_stopped = false;
    /// The bit rates (bit/s) the device supports, e.g. the BaudRate_ entries of its EDS (CiA 306
    /// 4.4): configure bit timing accepts these. Empty: every rate of the standard table when the
    /// device has a switch_bit_rate hook, none without.
    std::set<std::uint32_t> bit_rates;
};

/// How the slave reaches the device it belongs to. Every hook is optional; what a missing hook
/// means is said at the hook.
struct LssSlaveHooks {
    /// Writes the configuration to non-volatile memory. Missing: store is "not supported".
    std::function<LssStoreResult(const LssConfiguration&)> store_configuration;
    /// Switches the device's CAN controller to `bit_rate` (bit/s), at the end of the first
    /// switch delay of activate bit timing. Missing: the active bit rate changes in the slave
    /// only; without LssSlaveConfig::bit_rates either, the device cannot change its bit rate, so
    /// configure bit timing answers "not supported" and activate bit timing is ignored.
    std::function<void(std::uint32_t bit_rate)> switch_bit_rate;
    /// Told when the device must stop sending (true) and may send again (false): the two switch
    /// delays of activate bit timing. The device's other services check silent() too.
    std::function<void(bool silent)> on_silence;
    /// CiA 305: a slave that had no node-ID and got one performs NMT reset communication when
    /// it is switched back to waiting; the device does it and then calls reset_communication().
    std::function<void()> request_reset_communication;
};

/// The LSS slave of a node (CiA 305, EPOS2 FW spec 7.4): the LSS states waiting and
/// configuration, switch state global and selective, configure node-ID and bit timing, activate
/// bit timing, store configuration, inquire identity and node-ID, identify remote slave and
/// non-configured remote slave, and fastscan. It listens to kLssMasterCobId and answers on
/// kLssSlaveCobId; commands that are not allowed in the current LSS state are ignored, as are
/// frames without 8 data bytes.
///
/// A configured node-ID is pending until the device's next reset communication, which makes it
/// active (reset_communication()); a configured bit rate is pending until activate bit timing,
/// which ignores the bus for the first switch delay (the controller switches at its end) and
/// holds back the slave's answers until the end of the second.
class LssSlave {
public:
    LssSlave(core::EventLoop& loop, can::Port& port, LssAddress address, LssSlaveConfig config = {},
             LssSlaveHooks hooks = {});
    LssSlave(const LssSlave&) = delete;
    LssSlave& operator=(const LssSlave&) = delete;

    void on_frame(const can::Frame& frame);
    void set_nmt_state(NmtState state) { nmt_state_ = state; }

    /// NMT reset communication: the pending node-ID becomes active, the slave is back in
    /// waiting. Returns the active node-ID.
    NodeId reset_communication();

    LssState state() const { return state_; }
    const LssAddress& address() const { return address_; }
    NodeId active_node_id() const { return active_.node_id; }
    NodeId pending_node_id() const { return pending_.node_id; }
    std::uint32_t active_bit_rate() const { return active_.bit_rate; }
    std::uint32_t pending_bit_rate() const { return pending_.bit_rate; }
    /// True during the two switch delays of activate bit timing: the node sends nothing.
    bool silent() const { return switch_phase_ != SwitchPhase::None; }

private:
    bool accessible() const;
    bool supports(std::uint32_t bit_rate) const;
    bool switches_bit_rate() const;
    bool non_configured() const;
    void enter(LssState state);
    bool on_command_of_any_state(LssCommand cs, const can::Frame& frame);
    void on_waiting_command(LssCommand cs, const can::Frame& frame);
    void on_configuration_command(LssCommand cs, const can::Frame& frame);
    void switch_state_global(std::uint8_t mode);
    void switch_state_selective(LssCommand cs, std::uint32_t value);
    void identify_remote_slave(LssCommand cs, std::uint32_t value);
    void identify_non_configured_remote_slave();
    void fastscan(const can::Frame& frame);
    void configure_node_id(NodeId id);
    void configure_bit_timing(std::uint8_t table_selector, std::uint8_t table_index);
    void activate_bit_timing(std::uint16_t switch_delay_ms);
    void end_first_switch_delay(core::Duration switch_delay);
    void store_configuration();
    void end_silence();
    void respond(LssCommand cs, std::initializer_list<std::uint8_t> bytes = {});
    void send(const can::Frame& frame);

    /// EPOS2 FW spec 7.4.2.5, figure 7-65: the two switch delays of activate bit timing.
    enum class SwitchPhase : std::uint8_t {
        None,
        Switching, ///< first delay: the controller changes its bit rate at its end
        Settling,  ///< second delay: listening on the new bit rate, not yet sending
    };

    core::EventLoop& loop_;
    can::Port& port_;
    LssAddress address_;
    LssSlaveConfig config_;
    LssSlaveHooks hooks_;
    NmtState nmt_state_ = NmtState::Initialising;
    LssState state_ = LssState::Waiting;
    LssConfiguration active_;
    LssConfiguration pending_;
    /// How many parts of switch state selective (0x40..) and identify remote slave (0x46..)
    /// have arrived in order and matched; a frame out of order or a mismatch starts over.
    std::uint8_t selective_matched_ = 0;
    std::uint8_t identify_matched_ = 0;
    /// Fastscan's LSSPos: the address part this slave compares next (CiA 305).
    LssPart fastscan_position_ = LssPart::VendorId;
    SwitchPhase switch_phase_ = SwitchPhase::None;
    std::vector<can::Frame> held_; ///< answers made while settling, sent when it ends
    core::ScopedTimer switch_timer_;
};

} // namespace eposp::canopen
