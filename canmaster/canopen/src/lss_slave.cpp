#include "eposp/canopen/lss_slave.hpp"

#include "eposp/canopen/object_dictionary.hpp"

#include <chrono>
#include <utility>

namespace eposp::canopen {

namespace {

constexpr std::uint16_t kIdentityObject = 0x1018;

/// Byte 0 of an LSS frame, for the arithmetic on runs of command specifiers (0x40..0x43).
std::uint8_t code(LssCommand cs) {
    return static_cast<std::uint8_t>(cs);
}

} // namespace

LssAddress lss_address_from_dictionary(const ObjectDictionary& dictionary) {
    return {dictionary.get_as<std::uint32_t>(kIdentityObject, 1),
            dictionary.get_as<std::uint32_t>(kIdentityObject, 2),
            dictionary.get_as<std::uint32_t>(kIdentityObject, 3),
            dictionary.get_as<std::uint32_t>(kIdentityObject, 4)};
}

LssSlave::LssSlave(core::EventLoop& loop, can::Port& port, LssAddress address,
                   LssSlaveConfig config, LssSlaveHooks hooks)
    : loop_(loop), port_(port), address_(address), config_(config), hooks_(std::move(hooks)),
      active_(config.initial), pending_(config.initial) {}

void LssSlave::on_frame(const can::Frame& frame) {
    const std::optional<LssCommand> cs = lss_command(frame, kLssMasterCobId);
    // While it switches its bit rate the node takes no part in the bus (7.4.2.5).
    if (!cs || switch_phase_ == SwitchPhase::Switching || !accessible()) {
        return;
    }
    if (on_command_of_any_state(*cs, frame)) {
        return;
    }
    if (state_ == LssState::Waiting) {
        on_waiting_command(*cs, frame);
    } else {
        on_configuration_command(*cs, frame);
    }
}

NodeId LssSlave::reset_communication() {
    active_.node_id = pending_.node_id;
    enter(LssState::Waiting);
    fastscan_position_ = LssPart::VendorId;
    return active_.node_id;
}

bool LssSlave::accessible() const {
    return !config_.only_when_nmt_stopped || nmt_state_ == NmtState::Stopped ||
           !is_configured_node_id(active_.node_id);
}

bool LssSlave::non_configured() const {
    return !is_configured_node_id(active_.node_id) && !is_configured_node_id(pending_.node_id);
}

void LssSlave::enter(LssState state) {
    state_ = state;
    selective_matched_ = 0;
    identify_matched_ = 0;
}

// EPOS2 FW spec 7.4.1, table 7-66: what each LSS state accepts. These commands are accepted in
// both states; returns false for the others.
bool LssSlave::on_command_of_any_state(LssCommand cs, const can::Frame& frame) {
    switch (cs) {
    case LssCommand::SwitchStateGlobal:
        switch_state_global(frame.data[1]);
        return true;
    case LssCommand::IdentifyRemoteSlaveVendorId:
    case LssCommand::IdentifyRemoteSlaveProductCode:
    case LssCommand::IdentifyRemoteSlaveRevisionLow:
    case LssCommand::IdentifyRemoteSlaveRevisionHigh:
    case LssCommand::IdentifyRemoteSlaveSerialLow:
    case LssCommand::IdentifyRemoteSlaveSerialHigh:
        identify_remote_slave(cs, lss_u32(frame));
        return true;
    case LssCommand::IdentifyNonConfiguredRemoteSlave:
        identify_non_configured_remote_slave();
        return true;
    default:
        return false;
    }
}

void LssSlave::on_waiting_command(LssCommand cs, const can::Frame& frame) {
    switch (cs) {
    case LssCommand::SwitchStateSelectiveVendorId:
    case LssCommand::SwitchStateSelectiveProductCode:
    case LssCommand::SwitchStateSelectiveRevisionNumber:
    case LssCommand::SwitchStateSelectiveSerialNumber:
        switch_state_selective(cs, lss_u32(frame));
        break;
    case LssCommand::Fastscan:
        fastscan(frame);
        break;
    default:
        break;
    }
}

void LssSlave::on_configuration_command(LssCommand cs, const can::Frame& frame) {
    switch (cs) {
    case LssCommand::ConfigureNodeId:
        configure_node_id(frame.data[1]);
        break;
    case LssCommand::ConfigureBitTiming:
        configure_bit_timing(frame.data[1], frame.data[2]);
        break;
    case LssCommand::ActivateBitTiming:
        activate_bit_timing(lss_u16(frame));
        break;
    case LssCommand::StoreConfiguration:
        store_configuration();
        break;
    case LssCommand::InquireVendorId:
    case LssCommand::InquireProductCode:
    case LssCommand::InquireRevisionNumber:
    case LssCommand::InquireSerialNumber: {
        const auto part = static_cast<LssPart>(code(cs) - code(LssCommand::InquireVendorId));
        send(lss_frame_u32(kLssSlaveCobId, cs, address_.part(part)));
        break;
    }
    case LssCommand::InquireNodeId:
        respond(cs, {active_.node_id});
        break;
    default:
        break;
    }
}

// 7.4.2.1: mode 0 waiting, 1 configuration; other modes are not defined and ignored.
void LssSlave::switch_state_global(std::uint8_t mode) {
    if (mode == static_cast<std::uint8_t>(LssState::Configuration)) {
        enter(LssState::Configuration);
        return;
    }
    if (mode != static_cast<std::uint8_t>(LssState::Waiting)) {
        return;
    }
    // CiA 305: a device without node-ID that got one leaves LSS through reset communication.
    const bool got_first_node_id = state_ == LssState::Configuration &&
                                   !is_configured_node_id(active_.node_id) &&
                                   is_configured_node_id(pending_.node_id);
    enter(LssState::Waiting);
    if (got_first_node_id && hooks_.request_reset_communication) {
        hooks_.request_reset_communication();
    }
}

// 7.4.2.2: vendor-ID, product code, revision number, serial number in this order; the slave
// whose address they all match switches to configuration and confirms.
void LssSlave::switch_state_selective(LssCommand cs, std::uint32_t value) {
    const auto index =
        static_cast<std::uint8_t>(code(cs) - code(LssCommand::SwitchStateSelectiveVendorId));
    const bool in_order = index == 0 || index == selective_matched_;
    if (!in_order || value != address_.part(static_cast<LssPart>(index))) {
        selective_matched_ = 0;
        return;
    }
    selective_matched_ = static_cast<std::uint8_t>(index + 1);
    if (selective_matched_ == kLssPartCount) {
        enter(LssState::Configuration);
        respond(LssCommand::SwitchStateSelectiveResponse);
    }
}

// 7.4.2.12: vendor-ID and product code equal, revision and serial number within [low, high].
void LssSlave::identify_remote_slave(LssCommand cs, std::uint32_t value) {
    const auto index =
        static_cast<std::uint8_t>(code(cs) - code(LssCommand::IdentifyRemoteSlaveVendorId));
    bool matches = false;
    switch (cs) {
    case LssCommand::IdentifyRemoteSlaveVendorId:
        matches = value == address_.vendor_id;
        break;
    case LssCommand::IdentifyRemoteSlaveProductCode:
        matches = value == address_.product_code;
        break;
    case LssCommand::IdentifyRemoteSlaveRevisionLow:
        matches = value <= address_.revision_number;
        break;
    case LssCommand::IdentifyRemoteSlaveRevisionHigh:
        matches = value >= address_.revision_number;
        break;
    case LssCommand::IdentifyRemoteSlaveSerialLow:
        matches = value <= address_.serial_number;
        break;
    default: // IdentifyRemoteSlaveSerialHigh
        matches = value >= address_.serial_number;
        break;
    }
    const bool in_order = index == 0 || index == identify_matched_;
    if (!in_order || !matches) {
        identify_matched_ = 0;
        return;
    }
    identify_matched_ = static_cast<std::uint8_t>(index + 1);
    if (cs == LssCommand::IdentifyRemoteSlaveSerialHigh) {
        identify_matched_ = 0;
        respond(LssCommand::IdentifySlave);
    }
}

// 7.4.2.13: every slave without a node-ID (0 or 0xFF, active and pending) answers.
void LssSlave::identify_non_configured_remote_slave() {
    if (non_configured()) {
        respond(LssCommand::IdentifyNonConfiguredSlave);
    }
}

// CiA 305 fastscan: non-configured slaves in waiting compare bits bit_checked..31 of the
// requested address part; a confirm (BitChecked 0x80) restarts them at the vendor-ID. A slave
// that matched all bits of a part goes on with LSSNext; going back (LSSNext < LSSSub) after the
// last part means the whole address matched, and the slave switches to configuration.
void LssSlave::fastscan(const can::Frame& frame) {
    const std::optional<FastscanRequest> request = lss_fastscan_request(frame);
    if (!request || !non_configured()) {
        return;
    }
    if (request->bit_checked == kFastscanConfirm) {
        fastscan_position_ = LssPart::VendorId;
        respond(LssCommand::IdentifySlave);
        return;
    }
    if (request->sub != fastscan_position_) {
        return;
    }
    const std::uint32_t mask = ~std::uint32_t{0} << request->bit_checked;
    if (((request->id_number ^ address_.part(request->sub)) & mask) != 0) {
        return;
    }
    fastscan_position_ = request->next;
    if (request->bit_checked == 0 && request->next < request->sub) {
        enter(LssState::Configuration);
    }
    respond(LssCommand::IdentifySlave);
}

// 7.4.2.3: 1..127, or 0xFF to remove the node-ID; anything else is out of range.
void LssSlave::configure_node_id(NodeId id) {
    if (!is_lss_node_id(id)) {
        respond(LssCommand::ConfigureNodeId, {kLssNodeIdOutOfRange, 0});
        return;
    }
    pending_.node_id = id;
    respond(LssCommand::ConfigureNodeId, {kLssSuccess, 0});
}

bool LssSlave::switches_bit_rate() const {
    return hooks_.switch_bit_rate || !config_.bit_rates.empty();
}

bool LssSlave::supports(std::uint32_t bit_rate) const {
    return config_.bit_rates.empty() ? static_cast<bool>(hooks_.switch_bit_rate)
                                     : config_.bit_rates.contains(bit_rate);
}

// 7.4.2.4: the rate is pending until activate bit timing.
void LssSlave::configure_bit_timing(std::uint8_t table_selector, std::uint8_t table_index) {
    const std::optional<std::uint32_t> bit_rate = lss_bit_rate(table_selector, table_index);
    if (!bit_rate || !supports(*bit_rate)) {
        respond(LssCommand::ConfigureBitTiming, {kLssBitTimingNotSupported, 0});
        return;
    }
    pending_.bit_rate = *bit_rate;
    respond(LssCommand::ConfigureBitTiming, {kLssSuccess, 0});
}

// 7.4.2.5, figure 7-65: deaf and silent for one switch delay, switch, silent for another.
void LssSlave::activate_bit_timing(std::uint16_t switch_delay_ms) {
    if (!switches_bit_rate()) {
        return;
    }
    const core::Duration switch_delay = std::chrono::milliseconds(switch_delay_ms);
    switch_phase_ = SwitchPhase::Switching;
    if (hooks_.on_silence) {
        hooks_.on_silence(true);
    }
    switch_timer_ = core::ScopedTimer(loop_, loop_.after(switch_delay, [this, switch_delay] {
        end_first_switch_delay(switch_delay);
    }));
}

void LssSlave::end_first_switch_delay(core::Duration switch_delay) {
    switch_phase_ = SwitchPhase::Settling;
    active_.bit_rate = pending_.bit_rate;
    if (hooks_.switch_bit_rate) {
        hooks_.switch_bit_rate(active_.bit_rate);
    }
    switch_timer_ = core::ScopedTimer(loop_, loop_.after(switch_delay, [this] { end_silence(); }));
}

void LssSlave::end_silence() {
    switch_phase_ = SwitchPhase::None;
    if (hooks_.on_silence) {
        hooks_.on_silence(false);
    }
    for (const can::Frame& frame : std::exchange(held_, {})) {
        port_.send(frame);
    }
}

// 7.4.2.6: stores the pending node-ID and bit rate.
void LssSlave::store_configuration() {
    const LssStoreResult result = hooks_.store_configuration ? hooks_.store_configuration(pending_)
                                                             : LssStoreResult::NotSupported;
    respond(LssCommand::StoreConfiguration, {static_cast<std::uint8_t>(result), 0});
}

void LssSlave::respond(LssCommand cs, std::initializer_list<std::uint8_t> bytes) {
    send(lss_frame(kLssSlaveCobId, cs, bytes));
}

void LssSlave::send(const can::Frame& frame) {
    if (silent()) {
        held_.push_back(frame);
    } else {
        port_.send(frame);
    }
}

} // namespace eposp::canopen
