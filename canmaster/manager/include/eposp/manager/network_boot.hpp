#pragma once

#include "eposp/canopen/heartbeat_consumer.hpp"
#include "eposp/canopen/nmt_master.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/manager/network_list.hpp"
#include "eposp/manager/slave_boot.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace eposp::manager {

/// An error or warning for the error history (EPOS P firmware specification 10.4, table 4):
/// table 1's code for a node of the port (0: the master itself).
struct ManagerError {
    canopen::NodeId node = 0;
    std::uint16_t code = 0;
    bool warning = false; ///< an optional slave: reported, the network starts anyway
};

/// 0x8130 (table 1): a slave's heartbeat stayed away.
inline constexpr std::uint16_t kLifeguardError = 0x8130;

struct BootReport {
    std::vector<SlaveBootResult> slaves; ///< in the order they finished
    bool network_started = false;        ///< every mandatory slave booted and NMT start went out
};

/// The services of the manager's node on the port it boots.
struct ManagerServices {
    canopen::SdoClient& sdo;
    canopen::NmtMaster& nmt;
    canopen::HeartbeatConsumer& heartbeat;
};

/// The CiA 302 configuration manager and NMT master of one port: the network boot-up of EPOS P
/// firmware specification 8.1 (figure 3, CiA 302-2). start() resets the slaves' communication,
/// gives them the boot time, then boots every assigned slave at once (SlaveBoot). A mandatory
/// node that is not assigned as a slave fails at once (0x6388). When every mandatory slave has
/// booted, the slaves are started as 0x1F80 says: all with one "start remote node" to node 0,
/// or one by one (also when an optional slave failed, so that it is not started), or not at all
/// (the application starts them); then the master itself becomes operational unless 0x1F80 says
/// the application does it. A failed mandatory slave holds the start back; failed optional
/// ones are reported as warnings and skipped.
///
/// Afterwards a slave's boot-up message (a late slave, or one that re-booted) boots it again,
/// and starts it once booted if the network runs; a network held back starts as soon as its
/// last mandatory slave booted. A slave whose heartbeat stays away is a lifeguard error (0x8130)
/// and is reported lost.
///
/// The services must outlive it; it registers listeners with the heartbeat consumer for as long
/// as the consumer lives, so it must not be destroyed before the consumer stops delivering.
class NetworkBoot {
public:
    using ErrorSink = std::function<void(const ManagerError& error)>;

    NetworkBoot(core::EventLoop& loop, ManagerServices services, ErrorSink errors);
    ~NetworkBoot();
    NetworkBoot(const NetworkBoot&) = delete;
    NetworkBoot& operator=(const NetworkBoot&) = delete;

    /// Begins the boot-up of the network `list` describes (again, at a cold or warm start of the
    /// application: the boot in progress is dropped); `done` is told once, when every slave's
    /// boot has ended.
    void start(NetworkList list, std::function<void(const BootReport& report)> done = {});
    /// The master became operational (0x1F80 bit 2 clear), at the network start.
    void on_master_operational(std::function<void()> handler);
    /// Every mandatory slave booted and the start commands went out.
    void on_network_started(std::function<void()> handler);
    /// A slave was lost (heartbeat) or booted again after a boot-up message.
    void on_slave_lost(std::function<void(canopen::NodeId node)> handler);
    void on_slave_booted(std::function<void(canopen::NodeId node)> handler);

    const BootReport& report() const { return report_; }
    /// The slave booted (initially or since its last boot-up) and was not lost since.
    bool booted(canopen::NodeId node) const;

private:
    const SlaveEntry* entry(canopen::NodeId node) const;
    /// A network without assigned slaves gets no NMT command: the master leaves nodes it does
    /// not manage alone.
    bool has_slaves() const;
    void boot_all();
    void boot(const SlaveEntry& slave);
    void on_booted(const SlaveBootResult& result);
    /// A slave's boot ended: into the report, and its error (a warning for an optional one).
    void record(const SlaveBootResult& result);
    /// Every slave of the initial boot has ended: the network starts if it may, `done` is told.
    void finish_initial_boot();
    void on_heartbeat(canopen::NodeId node, canopen::NmtState state);
    void on_heartbeat_lost(canopen::NodeId node);
    void start_network_when_ready();
    void start_slave(canopen::NodeId node);

    core::EventLoop& loop_;
    ManagerServices services_;
    NetworkList list_;
    ErrorSink errors_;
    std::function<void(const BootReport&)> done_;
    std::function<void()> master_operational_;
    std::function<void()> network_started_;
    std::function<void(canopen::NodeId)> slave_lost_;
    std::function<void(canopen::NodeId)> slave_booted_;
    BootReport report_;
    bool boot_time_over_ = false;
    bool initial_boot_reported_ = false;
    std::map<canopen::NodeId, std::unique_ptr<SlaveBoot>> boots_;
    /// The outcome of each slave's last boot: true booted, false failed.
    std::map<canopen::NodeId, bool> booted_;
    std::vector<std::unique_ptr<SlaveBoot>> finished_boots_; ///< freed outside their callback
    core::ScopedTimer boot_timer_;
    core::ScopedTimer cleanup_timer_;
};

} // namespace eposp::manager
