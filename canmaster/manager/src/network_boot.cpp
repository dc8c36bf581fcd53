#include "eposp/manager/network_boot.hpp"

#include <algorithm>
#include <utility>

namespace eposp::manager {

NetworkBoot::NetworkBoot(core::EventLoop& loop, ManagerServices services, ErrorSink errors)
    : loop_(loop), services_(services), errors_(std::move(errors)) {
    services_.heartbeat.on_state_change(
        [this](canopen::NodeId node, canopen::NmtState state) { on_heartbeat(node, state); });
    services_.heartbeat.on_timeout([this](canopen::NodeId node) { on_heartbeat_lost(node); });
}

NetworkBoot::~NetworkBoot() = default;

void NetworkBoot::on_master_operational(std::function<void()> handler) {
    master_operational_ = std::move(handler);
}

void NetworkBoot::on_network_started(std::function<void()> handler) {
    network_started_ = std::move(handler);
}

void NetworkBoot::on_slave_lost(std::function<void(canopen::NodeId node)> handler) {
    slave_lost_ = std::move(handler);
}

void NetworkBoot::on_slave_booted(std::function<void(canopen::NodeId node)> handler) {
    slave_booted_ = std::move(handler);
}

const SlaveEntry* NetworkBoot::entry(canopen::NodeId node) const {
    for (const SlaveEntry& slave : list_.slaves) {
        if (slave.node_id == node && slave.assigned()) {
            return &slave;
        }
    }
    return nullptr;
}

bool NetworkBoot::has_slaves() const {
    return std::ranges::any_of(list_.slaves,
                               [](const SlaveEntry& slave) { return slave.assigned(); });
}

bool NetworkBoot::booted(canopen::NodeId node) const {
    const auto found = booted_.find(node);
    return found != booted_.end() && found->second;
}

void NetworkBoot::start(NetworkList list, std::function<void(const BootReport& report)> done) {
    list_ = std::move(list);
    done_ = std::move(done);
    report_ = {};
    booted_.clear();
    boots_.clear();
    boot_time_over_ = false;
    initial_boot_reported_ = false;
    for (const SlaveEntry& slave : list_.slaves) {
        if (slave.mandatory() && !slave.assigned()) {
            SlaveBootResult result;
            result.node = slave.node_id;
            result.error = BootError::NotSlave;
            record(result);
        }
    }
    // CiA 302-2: the slaves start from a known state, and their boot-up messages show who is
    // there; the boot time gives them room to send them.
    if ((list_.nmt_startup & nmt_startup::kMaster) != 0 && has_slaves()) {
        services_.nmt.send(canopen::NmtCommand::ResetCommunication, canopen::kAllNodes);
    }
    boot_timer_ = core::ScopedTimer(loop_, loop_.after(list_.boot_time, [this] {
        boot_time_over_ = true;
        boot_all();
    }));
}

void NetworkBoot::boot_all() {
    for (const SlaveEntry& slave : list_.slaves) {
        if (slave.assigned()) {
            boot(slave);
        }
    }
    if (boots_.empty()) {
        finish_initial_boot();
    }
}

void NetworkBoot::finish_initial_boot() {
    initial_boot_reported_ = true;
    start_network_when_ready();
    if (done_) {
        done_(report_);
    }
}

void NetworkBoot::record(const SlaveBootResult& result) {
    report_.slaves.push_back(result);
    booted_[result.node] = !result.error;
    if (result.error) {
        const SlaveEntry* slave = entry(result.node);
        errors_({.node = result.node,
                 .code = static_cast<std::uint16_t>(*result.error),
                 .warning = slave != nullptr && !slave->mandatory()});
    }
}

void NetworkBoot::boot(const SlaveEntry& slave) {
    SlaveEntry checked = slave;
    if (!slave.may_boot()) {
        checked.configuration.clear(); // 0x1F81 bit 2 clear: checked, not configured
    }
    booted_[slave.node_id] = false;
    auto boot =
        std::make_unique<SlaveBoot>(loop_, services_.sdo, std::move(checked),
                                    [this](const SlaveBootResult& result) { on_booted(result); });
    SlaveBoot& started = *boot;
    boots_[slave.node_id] = std::move(boot);
    // A boot-up message proves the node is there, not that it produces heartbeats.
    const auto state = services_.heartbeat.remote_state(slave.node_id);
    started.start(state.has_value() && *state != canopen::NmtState::Initialising);
}

void NetworkBoot::on_booted(const SlaveBootResult& result) {
    // The boot calls from inside itself: it is freed once this event is over.
    if (auto found = boots_.find(result.node); found != boots_.end()) {
        finished_boots_.push_back(std::move(found->second));
        boots_.erase(found);
        cleanup_timer_ = core::ScopedTimer(loop_, loop_.post([this] { finished_boots_.clear(); }));
    }
    record(result);
    if (!initial_boot_reported_) {
        if (boots_.empty()) {
            finish_initial_boot();
        }
        return;
    }
    // A slave booted after the network boot: late, or again after a reset.
    if (result.error) {
        return;
    }
    if (report_.network_started) {
        start_slave(result.node);
    } else {
        start_network_when_ready();
    }
    if (slave_booted_) {
        slave_booted_(result.node);
    }
}

void NetworkBoot::start_network_when_ready() {
    if (report_.network_started) {
        return;
    }
    bool all_booted = true;
    for (const SlaveEntry& slave : list_.slaves) {
        if (slave.mandatory() && !booted(slave.node_id)) {
            return;
        }
        all_booted = all_booted && (!slave.assigned() || booted(slave.node_id));
    }
    report_.network_started = true;
    if ((list_.nmt_startup & nmt_startup::kDoNotStartSlaves) == 0 && has_slaves()) {
        // Node 0 would also start an optional slave that failed its checks.
        if ((list_.nmt_startup & nmt_startup::kStartAllNodes) != 0 && all_booted) {
            services_.nmt.send(canopen::NmtCommand::Start, canopen::kAllNodes);
        } else {
            for (const SlaveEntry& slave : list_.slaves) {
                if (slave.assigned() && booted(slave.node_id)) {
                    start_slave(slave.node_id);
                }
            }
        }
    }
    if (network_started_) {
        network_started_();
    }
    if ((list_.nmt_startup & nmt_startup::kNotSelfStarting) == 0 && master_operational_) {
        master_operational_();
    }
}

void NetworkBoot::start_slave(canopen::NodeId node) {
    const SlaveEntry* slave = entry(node);
    if (slave != nullptr && slave->may_boot() &&
        (list_.nmt_startup & nmt_startup::kDoNotStartSlaves) == 0) {
        services_.nmt.send(canopen::NmtCommand::Start, node);
    }
}

void NetworkBoot::on_heartbeat(canopen::NodeId node, canopen::NmtState state) {
    if (!boot_time_over_) {
        return; // the boot-up messages after the reset: boot_all() comes next
    }
    if (const auto running = boots_.find(node); running != boots_.end()) {
        if (state != canopen::NmtState::Initialising) {
            running->second->heartbeat_received();
        } else {
            running->second->node_restarted();
        }
        return;
    }
    const SlaveEntry* slave = entry(node);
    if (slave == nullptr) {
        return;
    }
    // A boot-up message mid-run (the slave reset), or the first sign of a slave that was lost
    // or had failed: it is booted again.
    if (state == canopen::NmtState::Initialising || !booted(node)) {
        if (booted(node) && slave_lost_) {
            slave_lost_(node);
        }
        boot(*slave);
    }
}

void NetworkBoot::on_heartbeat_lost(canopen::NodeId node) {
    // Only a booted slave can be lost; a boot in progress judges the heartbeat itself (0x6387).
    if (entry(node) == nullptr || !booted(node) || boots_.contains(node)) {
        return;
    }
    booted_[node] = false;
    errors_({.node = node, .code = kLifeguardError, .warning = false});
    if (slave_lost_) {
        slave_lost_(node);
    }
}

} // namespace eposp::manager
