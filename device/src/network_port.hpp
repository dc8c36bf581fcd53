#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/emcy_consumer.hpp"
#include "eposp/canopen/heartbeat_consumer.hpp"
#include "eposp/canopen/heartbeat_producer.hpp"
#include "eposp/canopen/nmt_master.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/pdo_service.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/canopen/sdo_server.hpp"
#include "eposp/canopen/sync_consumer.hpp"
#include "eposp/canopen/sync_producer.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/manager/network_boot.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace eposp::device {

/// The network list of one port as the dictionary holds it (10.11, 10.20 - 10.30): on port 2
/// the slaves of sub-indices 1..127, on port 1 the internal EPOS2 (sub-index 128, node 1). Each
/// slave is configured to produce its heartbeat at half the consumer time 0x1016 watches it with,
/// then as `configurations` says for its node-ID (the axis PDO set-up of a network file).
using SlaveConfigurations = std::map<canopen::NodeId, std::vector<manager::ConfigurationWrite>>;
manager::NetworkList network_list(const canopen::ObjectDictionary& od, std::uint8_t port,
                                  const SlaveConfigurations& configurations = {});

/// Table 1: the CAN errors of a port.
inline constexpr std::uint16_t kCanOverrunError = 0x8110;
inline constexpr std::uint16_t kCanPassiveError = 0x8120;
inline constexpr std::uint16_t kCanWarning = 0x81FC;
inline constexpr std::uint16_t kCanBusOffError = 0x81FD;

/// The EPOS P as the CANopen manager of one of its ports: an SDO client, an NMT master and a
/// heartbeat consumer for the entries of 0x1016 with the port's code, and the network boot-up
/// of manager::NetworkBoot on the dictionary's network list; the SYNC producer of 0x1005 -
/// 0x1007 and the port's PDOs (port 1: 0x1500 / 0x1900 ..., port 2: 0x1400 / 0x1800 ...),
/// which run once the port's network started: its slaves' TPDOs land in the dictionary (the
/// axis table 0x5280 + n, the process image); and Request NMT 0x1F82 for the port's slaves. Its
/// errors, and the port's CAN errors (error passive 0x8120, bus-off 0x81FD, a lost frame 0x8110),
/// go to the error history with the port code and the node-ID (table 4).
///
/// On port 2 the EPOS P is also a node of its own, with the node-ID 0x5000 had at power-up: it
/// sends its heartbeat as 0x1017 says and serves its dictionary by SDO (0x600 / 0x580 +
/// node-ID), so a service tool on the bus reads and writes its objects.
class NetworkPort {
public:
    NetworkPort(core::EventLoop& loop, can::Port& port, canopen::ObjectDictionary& od,
                std::uint8_t port_code);
    ~NetworkPort();
    NetworkPort(const NetworkPort&) = delete;
    NetworkPort& operator=(const NetworkPort&) = delete;

    /// Boots the port's network as the dictionary configures it now; `done` is told once every
    /// slave's boot has ended.
    void boot(std::function<void(const manager::BootReport& report)> done = {});
    const manager::NetworkBoot& network() const { return network_; }
    /// The network list boot() starts from now.
    manager::NetworkList list() const { return network_list(od_, port_code_, configurations_); }
    /// What the boot writes into slave `node` after its checks passed (a concise DCF).
    void set_slave_configuration(canopen::NodeId node,
                                 std::vector<manager::ConfigurationWrite> writes) {
        configurations_[node] = std::move(writes);
    }
    /// Told of each SYNC the port sends, after its synchronous PDOs have been handled; every
    /// listener added is told, in the order they were added.
    void on_sync(std::function<void()> listener) { sync_listeners_.push_back(std::move(listener)); }
    /// The SDO client the manager reaches the port's slaves with (the motion blocks use it too).
    canopen::SdoClient& sdo() { return sdo_; }
    /// Its NMT master, for commands the application sends (CAN_Nmt).
    canopen::NmtMaster& nmt() { return nmt_; }
    core::EventLoop& loop() { return loop_; }
    /// Told of each EMCY a node on the port sends.
    void on_emergency(canopen::EmcyConsumer::Listener listener) {
        emcy_.on_emergency(std::move(listener));
    }
    /// Told each time RPDO `number` of the port (1..) has stored its data.
    void on_rpdo(std::size_t number, std::function<void()> listener) {
        pdo_.rpdo(number).on_applied(std::move(listener));
    }
    /// The port's controller lost a received frame (its queue was full).
    void report_lost_frame();
    /// Tells `observer` of every frame the port receives, after the port's services handled it
    /// (the service interface's CAN gateway); until stop_observing(), before the port dies.
    using FrameObserverId = std::uint64_t;
    FrameObserverId observe_frames(std::function<void(const can::Frame& frame)> observer);
    void stop_observing(FrameObserverId id) { frame_observers_.erase(id); }
    /// The controller's own node-ID on the port (port 2; 0 on port 1, where it has none).
    canopen::NodeId own_node_id() const { return own_node_id_; }
    /// Sends a frame of a service tool's (the CAN gateway) on the port.
    can::SendStatus send(const can::Frame& frame) { return port_.send(frame); }

private:
    void report_controller_state(can::ErrorState state);
    /// 0x1F82 Request NMT for this port's slaves (table 27).
    void bind_request_nmt();
    /// 0x1280 - 0x12FF: the SDO client's COB-IDs for each of this port's slaves.
    void bind_sdo_clients();
    /// An error of the port itself (node-ID 0) in the history.
    void record_port_error(std::uint16_t code);
    /// The state of the controller's own services on this port.
    void set_nmt_state(canopen::NmtState state);

    core::EventLoop& loop_;
    can::Port& port_;
    canopen::ObjectDictionary& od_;
    std::uint8_t port_code_;
    canopen::NodeId own_node_id_ = 0;
    canopen::SdoClient sdo_;
    canopen::NmtMaster nmt_;
    canopen::HeartbeatConsumer heartbeat_;
    canopen::SyncProducer sync_producer_;
    canopen::SyncConsumer sync_consumer_;
    canopen::PdoService pdo_;
    canopen::EmcyConsumer emcy_;
    manager::NetworkBoot network_;
    /// Port 2 only: the EPOS P's own node.
    std::unique_ptr<canopen::SdoServer> sdo_server_;
    std::unique_ptr<canopen::HeartbeatProducer> heartbeat_producer_;
    SlaveConfigurations configurations_;
    std::vector<std::function<void()>> sync_listeners_;
    std::map<FrameObserverId, std::function<void(const can::Frame&)>> frame_observers_;
    FrameObserverId next_frame_observer_ = 1;
    std::vector<canopen::ObjectDictionary::ListenerId> listeners_;
    can::ErrorState controller_state_ = can::ErrorState::Active;
};

} // namespace eposp::device
