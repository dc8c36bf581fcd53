#pragma once

#include "eposp/can/io/socketcan_port.hpp"
#include "eposp/can/io/socketcand_client_port.hpp"
#include "eposp/can/io/socketcand_server.hpp"
#include "eposp/can/port_bridge.hpp"
#include "eposp/can/trace_clock.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/device/run_control.hpp"
#include "eposp/device/trace_files.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eposp::device {

/// How a command hosts its simulated bus: the options `eposp bus`, `node` and `drive` share.
struct HostedBusOptions {
    std::string name = "can0";
    std::uint32_t bitrate = 1'000'000;
    std::optional<std::string> socketcand;
    /// --socketcand-queue, --socketcand-clients
    can::io::SocketcandLimits socketcand_limits = {};
    std::optional<std::string> socketcan;
    /// A socketcand server (HOST:PORT) whose bus `join_bus` this bus is bridged onto, so that
    /// the host's nodes sit on a bus another process serves.
    std::optional<std::string> join;
    std::string join_bus = "can0";
    std::optional<std::string> log;
    std::optional<std::string> pcap;
    std::optional<core::Duration> duration;
    bool virtual_time = false;
    bool force = false; ///< --force: the traces may replace existing files of another kind
};

/// A simulated CAN bus on its own event loop, as a long-running command hosts it: outside tools
/// join over socketcand or a bridged SocketCAN interface, or the bus itself joins a socketcand
/// server's (--join); traces record every frame, and the run lasts for --for or until
/// SIGINT/SIGTERM (or until a joined server goes away). The host acknowledges frames through a
/// "monitor" port like a logging interface on a real bus, so a single client's frames complete.
class HostedBus {
public:
    /// Validates the options, opens the traces, the socketcand server, the SocketCAN bridge and
    /// the joined server (waiting until it is in raw mode, so that no node's boot-up is sent
    /// before) and prints where they are; or says why one cannot be opened.
    static core::Result<std::unique_ptr<HostedBus>> open(const HostedBusOptions& options);

    ~HostedBus();
    HostedBus(const HostedBus&) = delete;
    HostedBus& operator=(const HostedBus&) = delete;

    core::EventLoop& loop() { return loop_; }
    can::VirtualBus& bus() { return bus_; }
    /// The socketcand address listened on, when serving socketcand.
    std::optional<std::string> socketcand_address() const;

    /// A port of the host's own (a simulated node, a replay): it lives as long as the bus, and
    /// the summary shows its statistics.
    can::VirtualPort& attach(const std::string& name);

    /// Runs until --for elapses, a signal comes, (virtual time) nothing is left to do, or the
    /// server of --join goes away (RunEnd::Lost); prints "interrupted" when a signal ended it.
    RunEnd run();
    /// The bus statistics and those of every port, the host's and the socketcand clients'
    /// (those that have left summed in one line, so that what they lost stays visible).
    void print_summary() const;

private:
    explicit HostedBus(const HostedBusOptions& options);
    std::optional<std::string> open_outside_world();
    std::optional<std::string> join_server();
    /// The port of a bridge to the outside: it buffers bursts (can::kGatewayTxQueueCapacity).
    can::VirtualPort& attach_gateway(const std::string& name);

    HostedBusOptions options_;
    core::EventLoop loop_;
    can::VirtualBus bus_;
    can::TraceClock clock_;
    std::unique_ptr<TraceFiles> traces_;
    bool join_lost_ = false;
    std::vector<std::unique_ptr<can::VirtualPort>> own_ports_;
    std::unique_ptr<can::io::SocketcandServer> server_;
    std::unique_ptr<can::io::SocketCanPort> socketcan_;
    std::unique_ptr<can::PortBridge> bridge_;
    std::unique_ptr<can::io::SocketcandClientPort> joined_;
    std::unique_ptr<can::PortBridge> join_bridge_;
};

} // namespace eposp::device
