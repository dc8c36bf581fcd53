#include "eposp/canopen/node.hpp"

#include "eposp/canopen/emergency.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/canopen/predefined_connection_set.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "lss_configuration_file.hpp"

#include <tuple>
#include <utility>
#include <vector>

namespace eposp::canopen {
namespace {

constexpr std::uint16_t kCommunicationAreaFirst = 0x1000;
constexpr std::uint16_t kCommunicationAreaLast = 0x1FFF;
constexpr std::uint16_t kStoreParametersIndex = 0x1010;

bool in_communication_area(std::uint16_t index) {
    return index >= kCommunicationAreaFirst && index <= kCommunicationAreaLast;
}

/// CiA 301 7.5.2.1 (1000h) and 7.5.2.22 (1018h); EPOS2 FW spec 8.2.1 / 8.2.16: both read-only.
void add_device_objects(ObjectDictionary& od, const NodeConfig& config) {
    if (od.find(kDeviceTypeIndex) == nullptr) {
        od.add_variable(kDeviceTypeIndex, "Device Type", DataType::Unsigned32, Access::ReadOnly,
                        encode(config.device_type));
    }
    if (od.find(kIdentityIndex) == nullptr) {
        od.add_object(kIdentityIndex, "Identity Object", ObjectCode::Record);
        const auto add = [&od](std::uint8_t sub, std::string name, std::uint32_t value) {
            od.add_sub(kIdentityIndex, sub, std::move(name), DataType::Unsigned32, Access::ReadOnly,
                       encode(value));
        };
        add(1, "Vendor-ID", config.identity.vendor_id);
        add(2, "Product Code", config.identity.product_code);
        add(3, "Revision Number", config.identity.revision_number);
        add(4, "Serial Number", config.identity.serial_number);
    }
}

/// The communication objects the services need, each only where the dictionary lacks it.
ObjectDictionary& add_missing_communication_objects(ObjectDictionary& od,
                                                    const NodeConfig& config) {
    add_device_objects(od, config);
    add_error_objects(od, config.error_history_capacity); // those an EDS lacks, its rules
    if (od.find(kCobIdSyncIndex) == nullptr) {
        add_sync_objects(od, config.sync);
    }
    if (od.find(kGuardTimeIndex) == nullptr) {
        add_node_guarding_objects(od);
    }
    if (od.find(kCobIdEmcyIndex) == nullptr) {
        add_emcy_objects(od, config.node_id, config.emcy_inhibit_time);
    }
    if (od.find(kConsumerHeartbeatTimeIndex) == nullptr) {
        add_heartbeat_consumer_objects(od, config.heartbeat_consumer_entries);
    }
    if (od.find(kProducerHeartbeatTimeIndex) == nullptr) {
        add_heartbeat_producer_object(od);
    }
    if (od.find(0x1200) == nullptr) {
        add_sdo_server_objects(od, config.node_id);
    }
    if (count_pdos(od, PdoDirection::Receive) == 0 && count_pdos(od, PdoDirection::Transmit) == 0) {
        add_pdo_objects(od, config.pdos ? *config.pdos : cia301_pdo_defaults(config.node_id, 4, 4));
    }
    // The objects an EDS brought: the services' rules hold for every node (CiA 301 7.5.2).
    enforce_sync_rules(od, config.sync);
    enforce_emcy_rules(od);
    enforce_heartbeat_consumer_rules(od);
    enforce_pdo_rules(od);
    return od;
}

/// Where store configuration keeps the LSS configuration: beside the parameter file.
std::optional<LssConfigurationFile> lss_configuration_file(const NodeConfig& config) {
    if (!config.parameter_file) {
        return std::nullopt;
    }
    std::filesystem::path path = *config.parameter_file;
    path += ".lss";
    return LssConfigurationFile(std::move(path));
}

/// The node-ID and bit rate a node starts with: those LSS stored, else the configuration's.
NodeConfig with_stored_lss_configuration(NodeConfig config, bool& refused) {
    const auto file = lss_configuration_file(config);
    if (!file) {
        return config;
    }
    const auto stored = file->load();
    refused = !stored;
    if (stored && stored->has_value()) {
        config.node_id = (*stored)->node_id;
        config.bit_rate = (*stored)->bit_rate;
    }
    return config;
}

} // namespace

std::uint8_t error_register_bits(std::uint16_t emcy_error_code) {
    if (emcy_error_code == kEmcySoftwareParameterError) {
        return error_register::kDeviceProfile; // EPOS2 FW spec table 4-11
    }
    const auto group = emcy_error_code & 0xFF00;
    return group == 0x8100 || group == 0x8200 ? error_register::kCommunication
                                              : error_register::kGeneric;
}

Node::Node(core::EventLoop& loop, can::Port& port, ObjectDictionary& dictionary, NodeConfig config)
    : port_(port), services_port_(port, lss_),
      config_(with_stored_lss_configuration(std::move(config), refused_store_to_report_)),
      od_(add_missing_communication_objects(dictionary, config_)),
      nmt_(services_port_, config_.node_id,
           {.application = [this] { reset_application(); },
            .communication =
                [this] {
                    reset_communication();
                }}),
      emcy_(loop, services_port_, od_, config_.generic_error_bit),
      sdo_(loop, services_port_, od_, config_.node_id, config_.sdo),
      heartbeat_producer_(loop, services_port_, od_, config_.node_id),
      heartbeat_consumer_(loop, od_, [this](std::uint16_t code) { raise_emergency(code); }),
      guarding_(loop, services_port_, od_, config_.node_id,
                [this](std::uint16_t code) { raise_emergency(code); }),
      sync_producer_(loop, services_port_, od_),
      sync_consumer_(loop, od_, [this](std::uint16_t code) { raise_emergency(code); }),
      pdo_(loop, services_port_, od_, [this](std::uint16_t code) { raise_emergency(code); }),
      lss_(loop, port, config_.identity,
           {.initial = {config_.node_id, config_.bit_rate},
            .only_when_nmt_stopped = config_.lss_only_when_stopped,
            .bit_rates = config_.bit_rates},
           lss_hooks()) {
    if (config_.parameter_file) {
        store_.emplace(od_, *config_.parameter_file);
        if (od_.find(kStoreParametersIndex) == nullptr) {
            add_store_restore_objects(od_, *store_, config_.store_restore);
            if (config_.restore_pdo_cob_ids) {
                add_restore_pdo_cob_ids_object(
                    od_, *store_, [this] { return node_id(); }, config_.store_restore);
            }
        }
    }
    const auto resolve = [this](std::uint16_t code) {
        resolve_emergency(code);
    };
    pdo_.on_error_resolved(resolve);
    sync_consumer_.on_error_resolved(resolve);
    heartbeat_consumer_.on_error_resolved(resolve);
    guarding_.on_error_resolved(resolve);
    nmt_.on_state_change([this](NmtState state) { set_nmt_state(state); });
    // A node does not receive its own frames: its own SYNCs reach its PDOs this way.
    sync_producer_.on_sent([this](const can::Frame& frame) { sync_consumer_.on_frame(frame); });
    sync_consumer_.synchronise(pdo_);
    route_frames();
    port_.on_receive([this](const can::Frame& frame) { router_.dispatch(frame); });
    router_.filter(port_);
    port_.on_error_state([this](can::ErrorState state) {
        if (state != can::ErrorState::BusOff) {
            emcy_.controller_recovered();
        }
        if (controller_state_handler_) {
            controller_state_handler_(state);
        }
    });
}

Node::~Node() {
    port_.on_receive({});
    port_.on_error_state({});
    for (const auto id : cob_id_listeners_) {
        od_.remove_listener(id);
    }
}

void Node::on_controller_state(std::function<void(can::ErrorState)> handler) {
    controller_state_handler_ = std::move(handler);
}

LssSlaveHooks Node::lss_hooks() {
    LssSlaveHooks hooks;
    if (const auto file = lss_configuration_file(config_)) {
        hooks.store_configuration = [file = *file](const LssConfiguration& configuration) {
            return file.store(configuration);
        };
    }
    hooks.switch_bit_rate = config_.switch_bit_rate;
    // CiA 305: a node that got its first node-ID leaves LSS through NMT initialisation.
    hooks.request_reset_communication = [this] {
        nmt_.apply(NmtCommand::ResetCommunication);
    };
    return hooks;
}

void Node::start() {
    // The bit rate may be one LSS stored rather than the one the owner configured.
    if (config_.switch_bit_rate) {
        config_.switch_bit_rate(config_.bit_rate);
    }
    nmt_.boot();
}

void Node::on_reset_application(std::function<void()> handler) {
    application_reset_handler_ = std::move(handler);
}

void Node::route_frames() {
    router_.add([](ReceiveKeys& keys) { keys.push_back(kLssMasterCobId); }, lss_);
    router_.add([](ReceiveKeys& keys) { keys.push_back(kNmtCanId); }, nmt_);
    router_.add([this](ReceiveKeys& keys) { sync_consumer_.receive_keys(keys); }, sync_consumer_);
    router_.add([this](ReceiveKeys& keys) { sdo_.receive_keys(keys); }, sdo_);
    router_.add([this](ReceiveKeys& keys) { pdo_.receive_keys(keys); }, pdo_);
    router_.add([this](ReceiveKeys& keys) { heartbeat_consumer_.receive_keys(keys); },
                heartbeat_consumer_);
    router_.add([this](ReceiveKeys& keys) { guarding_.receive_keys(keys); }, guarding_);
    // The objects the identifiers come from; reset communication (where a new node-ID takes
    // effect) invalidates too.
    std::vector<std::uint16_t> indices{kCobIdSyncIndex, kConsumerHeartbeatTimeIndex};
    for (std::size_t n = 1; n <= pdo_.rpdo_count(); ++n) {
        indices.push_back(pdo_communication_index(PdoDirection::Receive, n));
    }
    for (std::size_t n = 1; n <= pdo_.tpdo_count(); ++n) {
        indices.push_back(pdo_communication_index(PdoDirection::Transmit, n));
    }
    for (const std::uint16_t index : indices) {
        cob_id_listeners_.push_back(
            od_.on_change(index, [this](std::uint16_t, std::uint8_t) { router_.invalidate(); }));
    }
}

void Node::set_nmt_state(NmtState state) {
    emcy_.set_nmt_state(state);
    sdo_.set_nmt_state(state);
    heartbeat_producer_.set_nmt_state(state);
    heartbeat_consumer_.set_nmt_state(state);
    guarding_.set_nmt_state(state);
    sync_producer_.set_nmt_state(state);
    sync_consumer_.set_nmt_state(state);
    pdo_.set_nmt_state(state);
    lss_.set_nmt_state(state);
    if (state == NmtState::Initialising) {
        end_service_errors();
    }
    // The boot-up after the load: the first moment an EMCY may go out (EPOS2 FW spec 7.3.5).
    if (state == NmtState::PreOperational && refused_store_to_report_) {
        refused_store_to_report_ = false;
        raise_emergency(kEmcySoftwareParameterError);
    }
}

void Node::raise_emergency(std::uint16_t error_code) {
    if (service_errors_[error_code]++ == 0) {
        emcy_.raise(error_code, error_register_bits(error_code));
    }
}

void Node::resolve_emergency(std::uint16_t error_code) {
    const auto found = service_errors_.find(error_code);
    if (found != service_errors_.end() && --found->second == 0) {
        service_errors_.erase(found);
        emcy_.clear(error_code);
    }
}

// CiA 301 7.3.2.2.1: a reset brings the communication back to its power-on state, and with it
// 0x1001; what a service raised without an end of its own (0x8150, 0x6320) ends here too.
void Node::end_service_errors() {
    for (const auto& [code, causes] : service_errors_) {
        emcy_.clear(code);
    }
    service_errors_.clear();
}

void Node::restore_stored_values(bool communication_area_only) {
    // Neither the parameter store nor the dictionary restores one area alone: keep the rest.
    std::vector<std::tuple<std::uint16_t, std::uint8_t, Bytes>> kept;
    if (communication_area_only) {
        for (const auto& [index, object] : od_.objects()) {
            if (!in_communication_area(index)) {
                for (const auto& [sub_index, sub] : object.subs) {
                    kept.emplace_back(index, sub_index, sub.value);
                }
            }
        }
    }
    if (store_) {
        stored_values_ = store_->load_stored_values();
        refused_store_to_report_ = refused_store_to_report_ || stored_values_.refused();
    } else {
        od_.reset_to_defaults();
    }
    for (auto& [index, sub_index, value] : kept) {
        od_.find(index, sub_index)->value = std::move(value);
    }
}

// CiA 301 7.3.2.2.1: reset application, the manufacturer-specific and profile areas.
void Node::reset_application() {
    emcy_.clear_all(); // the device starts afresh: none of its errors is active
    restore_stored_values(false);
    if (application_reset_handler_) {
        application_reset_handler_();
    }
}

// CiA 301 7.3.2.2.1: reset communication, the communication area; the PDOs take its values.
// CiA 305: a node-ID that LSS configured becomes active here.
void Node::reset_communication() {
    adopt_node_id(lss_.reset_communication());
    restore_stored_values(true);
    pdo_.reload();
    router_.invalidate();
}

void Node::adopt_node_id(NodeId node_id) {
    if (node_id == nmt_.node_id()) {
        return;
    }
    move_node_id_defaults(od_, nmt_.node_id(), node_id);
    nmt_.set_node_id(node_id);
    sdo_.set_node_id(node_id);
    heartbeat_producer_.set_node_id(node_id);
    guarding_.set_node_id(node_id);
}

} // namespace eposp::canopen
