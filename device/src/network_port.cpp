#include "network_port.hpp"

#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/device/error_entry.hpp"

#include <chrono>
#include <utility>

namespace eposp::device {
namespace {

constexpr std::uint16_t kProducerHeartbeatIndex = 0x1017;
constexpr std::uint16_t kRequestNmtIndex = 0x1F82;
constexpr std::uint16_t kSdoClientIndex = 0x1280;
constexpr canopen::NodeId kInternalEposNodeId = 1;

/// The time 0x1016 gives the producer `node` of `port`, or 0.
std::uint16_t consumer_time_ms(const canopen::ObjectDictionary& od, std::uint8_t port,
                               canopen::NodeId node) {
    for (const auto& [sub_index, sub] : od.find(canopen::kConsumerHeartbeatTimeIndex)->subs) {
        if (sub_index == 0) {
            continue;
        }
        const auto entry = canopen::ConsumerHeartbeatEntry::decode(
            od.get_as<std::uint32_t>(canopen::kConsumerHeartbeatTimeIndex, sub_index));
        if (entry.used() && entry.port_code == port && entry.node == node) {
            return entry.time_ms;
        }
    }
    return 0;
}

manager::SlaveEntry slave_entry(const canopen::ObjectDictionary& od, std::uint8_t port,
                                std::uint8_t sub_index, canopen::NodeId node) {
    const auto at = [&od, sub_index](std::uint16_t index) {
        return od.get_as<std::uint32_t>(index, sub_index);
    };
    manager::SlaveEntry slave;
    slave.node_id = node;
    slave.assignment = at(0x1F81);
    slave.device_type = at(0x1F84);
    slave.identity = {.vendor_id = at(0x1F85),
                      .product_code = at(0x1F86),
                      .revision_number = at(0x1F87),
                      .serial_number = at(0x1F88)};
    slave.configuration_date = at(0x1F26);
    slave.configuration_time = at(0x1F27);
    const std::uint16_t consumer_ms = consumer_time_ms(od, port, node);
    slave.heartbeat = std::chrono::milliseconds(consumer_ms);
    if (consumer_ms != 0) {
        // Half the time the consumer allows: one lost heartbeat is no error yet.
        slave.configuration.push_back(
            {kProducerHeartbeatIndex, 0,
             canopen::encode(static_cast<std::uint16_t>(std::max(1, consumer_ms / 2)))});
    }
    return slave;
}

/// Table 27: the NMT state a read of 0x1F82 gives (0 unknown: no heartbeat heard).
std::uint32_t request_nmt_value(std::optional<canopen::NmtState> state) {
    if (!state) {
        return 0x00;
    }
    switch (*state) {
    case canopen::NmtState::Stopped:
        return 0x04;
    case canopen::NmtState::Operational:
        return 0x05;
    case canopen::NmtState::PreOperational:
        return 0x7F;
    default:
        return 0x00; // a boot-up message: the state that follows is not known yet
    }
}

/// Table 27: the NMT command a write of 0x1F82 asks for.
std::optional<canopen::NmtCommand> requested_command(std::uint32_t value) {
    switch (value) {
    case 0x04:
        return canopen::NmtCommand::Stop;
    case 0x05:
        return canopen::NmtCommand::Start;
    case 0x06:
        return canopen::NmtCommand::ResetNode;
    case 0x07:
        return canopen::NmtCommand::ResetCommunication;
    case 0x7F:
        return canopen::NmtCommand::EnterPreOperational;
    default:
        return std::nullopt;
    }
}

} // namespace

manager::NetworkList network_list(const canopen::ObjectDictionary& od, std::uint8_t port,
                                  const SlaveConfigurations& configurations) {
    manager::NetworkList list;
    list.nmt_startup = od.get_as<std::uint32_t>(0x1F80, 0);
    list.boot_time = std::chrono::milliseconds(od.get_as<std::uint32_t>(0x1F89, 0));
    if (port == kInternalPort) {
        list.slaves.push_back(slave_entry(od, port, kInternalSlaveSubIndex, kInternalEposNodeId));
    } else {
        for (std::uint8_t node = 1; node <= 127; ++node) {
            if (od.get_as<std::uint32_t>(0x1F81, node) != 0) {
                list.slaves.push_back(slave_entry(od, port, node, node));
            }
        }
    }
    for (manager::SlaveEntry& slave : list.slaves) {
        if (const auto found = configurations.find(slave.node_id); found != configurations.end()) {
            slave.configuration.insert(slave.configuration.end(), found->second.begin(),
                                       found->second.end());
        }
    }
    return list;
}

NetworkPort::NetworkPort(core::EventLoop& loop, can::Port& port, canopen::ObjectDictionary& od,
                         std::uint8_t port_code)
    : loop_(loop), port_(port), od_(od), port_code_(port_code), sdo_(loop, port), nmt_(port),
      heartbeat_(loop, od, {}, port_code), sync_producer_(loop, port, od),
      sync_consumer_(loop, od, [this](std::uint16_t code) { record_port_error(code); }),
      pdo_(
          loop, port, od, [this](std::uint16_t code) { record_port_error(code); },
          port_code == kInternalPort ? kFirstInternalPdo : 1),
      network_(loop, {sdo_, nmt_, heartbeat_}, [this](const manager::ManagerError& error) {
          record_error(od_, {.code = error.code,
                             .port = port_code_,
                             .node = error.node,
                             .warning = error.warning});
      }) {
    if (port_code == kExternalPort) {
        own_node_id_ = od.get_as<std::uint8_t>(kNodeIdIndex, 0);
        sdo_server_ = std::make_unique<canopen::SdoServer>(loop, port, od, own_node_id_);
        // No boot-up message: the manager's first frame is its reset of the slaves, and a
        // controller alone on its bus would only collect ACK errors with it.
        heartbeat_producer_ =
            std::make_unique<canopen::HeartbeatProducer>(loop, port, od, own_node_id_);
    }
    // The manager supervises from power-up on (it is never in NMT initialisation).
    heartbeat_.set_nmt_state(canopen::NmtState::PreOperational);
    set_nmt_state(canopen::NmtState::PreOperational);
    // The controller does not hear its own SYNCs: they reach its PDOs this way.
    sync_producer_.on_sent([this](const can::Frame& frame) { sync_consumer_.on_frame(frame); });
    sync_consumer_.on_sync([this](const canopen::SyncEvent& sync) {
        pdo_.on_sync(sync.counter.value_or(0));
        for (const auto& listener : sync_listeners_) {
            listener();
        }
    });
    sync_consumer_.on_window_closed([this] { pdo_.on_window_closed(); });
    // 8.1: the boot-up comes before the controller's own switch to operational.
    network_.on_network_started([this] { set_nmt_state(canopen::NmtState::Operational); });
    port_.on_receive([this](const can::Frame& frame) {
        if (sdo_server_) {
            sdo_server_->on_frame(frame);
        }
        sdo_.on_frame(frame);
        heartbeat_.on_frame(frame);
        sync_consumer_.on_frame(frame);
        pdo_.on_frame(frame);
        emcy_.on_frame(frame);
        // An observer may stop observing itself from its call.
        for (auto it = frame_observers_.begin(); it != frame_observers_.end();) {
            const auto next = std::next(it);
            it->second(frame);
            it = next;
        }
    });
    port_.on_error_state([this](can::ErrorState state) { report_controller_state(state); });
    bind_request_nmt();
    bind_sdo_clients();
}

NetworkPort::FrameObserverId
NetworkPort::observe_frames(std::function<void(const can::Frame& frame)> observer) {
    const FrameObserverId id = next_frame_observer_++;
    frame_observers_.emplace(id, std::move(observer));
    return id;
}

// 10.15: the client parameter 0x1280 is the internal EPOS2's, 0x1280 + n node n's of port 2.
// Its COB-IDs hold from the start and from every write on (an invalid one, bit 31, makes the
// transfers to that slave fail).
void NetworkPort::bind_sdo_clients() {
    const auto bind = [this](std::uint16_t index, canopen::NodeId node) {
        const auto apply = [this, index, node] {
            sdo_.set_cob_ids(node, od_.get_as<std::uint32_t>(index, 1),
                             od_.get_as<std::uint32_t>(index, 2));
        };
        apply();
        listeners_.push_back(od_.on_change(index, [apply](std::uint16_t, std::uint8_t sub_index) {
            if (sub_index == 1 || sub_index == 2) {
                apply();
            }
        }));
    };
    if (port_code_ == kInternalPort) {
        bind(kSdoClientIndex, kInternalEposNodeId);
        return;
    }
    for (std::uint8_t node = 1; node <= 127; ++node) {
        bind(static_cast<std::uint16_t>(kSdoClientIndex + node), node);
    }
}

// 10.24: sub-index n is node n of port 2, sub-index 128 the internal EPOS2 (node 1 of port 1).
void NetworkPort::bind_request_nmt() {
    const auto bind = [this](std::uint8_t sub_index, canopen::NodeId node) {
        canopen::SubObject& entry = *od_.find(kRequestNmtIndex, sub_index);
        entry.on_read = [this, node] {
            return canopen::encode(request_nmt_value(heartbeat_.remote_state(node)));
        };
        entry.on_write = [this, node](std::span<const std::uint8_t> value) {
            const auto command = requested_command(canopen::decode<std::uint32_t>(value));
            if (!command) {
                return canopen::AbortCode::InvalidValue;
            }
            nmt_.send(*command, node);
            return canopen::AbortCode::None;
        };
    };
    if (port_code_ == kInternalPort) {
        bind(kInternalSlaveSubIndex, kInternalEposNodeId);
        return;
    }
    for (std::uint8_t node = 1; node <= 127; ++node) {
        bind(node, node);
    }
}

// Table 1: the controller's state changes, node-ID 0 (the master's own port).
void NetworkPort::report_controller_state(can::ErrorState state) {
    const can::ErrorState before = std::exchange(controller_state_, state);
    if (state == can::ErrorState::Warning && before == can::ErrorState::Active) {
        // A warning entry: the controller still takes part (table 4's warning bit).
        record_error(od_, {.code = kCanWarning, .port = port_code_, .node = 0, .warning = true});
    } else if (state == can::ErrorState::Passive) {
        record_port_error(kCanPassiveError);
    } else if (state == can::ErrorState::BusOff) {
        record_port_error(kCanBusOffError);
    }
}

void NetworkPort::set_nmt_state(canopen::NmtState state) {
    emcy_.set_nmt_state(state);
    if (sdo_server_) {
        sdo_server_->set_nmt_state(state);
        heartbeat_producer_->set_nmt_state(state);
    }
    sync_producer_.set_nmt_state(state);
    sync_consumer_.set_nmt_state(state);
    pdo_.set_nmt_state(state);
}

// An error of the port itself; also the emergencies of the controller's own PDO and SYNC
// services (a short PDO: 0x8210).
void NetworkPort::record_port_error(std::uint16_t code) {
    record_error(od_, {.code = code, .port = port_code_, .node = 0, .warning = false});
}

void NetworkPort::report_lost_frame() {
    record_port_error(kCanOverrunError);
}

NetworkPort::~NetworkPort() {
    port_.on_receive({});
    port_.on_error_state({});
    for (const auto id : listeners_) {
        od_.remove_listener(id);
    }
}

void NetworkPort::boot(std::function<void(const manager::BootReport& report)> done) {
    set_nmt_state(canopen::NmtState::PreOperational);
    network_.start(list(), std::move(done));
}

} // namespace eposp::device
