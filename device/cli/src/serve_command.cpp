// `eposp serve [app.epx|FILES…] [--network net.yaml] [--socketcand HOST:PORT] [--socketcan IF]
// [--for 10s] [the options of run]`: the EPOS P in real time, its CAN bus (port 2) open to the
// outside: external slaves (`eposp drive epos2 --join`, python-canopen, real drives over
// SocketCAN) take part in its boot-up and control, and service tools reach its own SDO server.
// Without a program the networks boot alone. It runs until --for elapses or SIGINT / SIGTERM.
#include "commands.hpp"
#include "device_session.hpp"
#include "eposp/can/io/socketcan_port.hpp"
#include "eposp/can/port_bridge.hpp"
#include "eposp/can/trace_clock.hpp"
#include "eposp/device/run_control.hpp"
#include "eposp/device/socketcand_hosting.hpp"
#include "options.hpp"

#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <memory>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kCommand = "serve";

struct ServeOptions {
    SessionOptions session;
    std::optional<std::string> socketcand;
    std::optional<std::string> socketcan;
    std::optional<core::Duration> duration;
};

// Port 2 as the outside world reaches it. Declared after the session, destroyed before it.
struct OutsideWorld {
    std::unique_ptr<can::io::SocketcandServer> server;
    std::unique_ptr<can::io::SocketCanPort> socketcan;
    std::unique_ptr<can::VirtualPort> bridge_port;
    std::unique_ptr<can::PortBridge> bridge;
};

core::Result<OutsideWorld> open_outside_world(const ServeOptions& options, EposP& device) {
    OutsideWorld world;
    can::VirtualBus& bus = device.external_bus();
    if (options.socketcand) {
        const auto clock = can::TraceClock::aligned(
            device.loop().now(),
            std::chrono::time_point_cast<core::Duration>(std::chrono::system_clock::now()));
        auto server = serve_socketcand(bus, *options.socketcand, clock.epoch_offset());
        if (!server) {
            return core::Error{fmt::format("--socketcand: {}", server.error())};
        }
        world.server = std::move(*server);
    }
    if (options.socketcan) {
        auto port = can::io::SocketCanPort::open(device.loop(), *options.socketcan);
        if (!port) {
            return core::Error{fmt::format("--socketcan: {}", port.error())};
        }
        world.socketcan = std::move(*port);
        world.bridge_port = bus.connect("socketcan-" + *options.socketcan, can::kGatewayTxQueueCapacity);
        world.bridge = std::make_unique<can::PortBridge>(*world.socketcan, *world.bridge_port);
        fmt::print("socketcan: bridged {} onto bus {}\n", *options.socketcan, bus.config().name);
    }
    return world;
}

int serve(const ServeOptions& options) {
    auto session = DeviceSession::open(options.session, core::Pace::RealTime);
    if (!session) {
        return report_user_error(kCommand, session.error());
    }
    EposP& device = (*session)->device();
    auto world = open_outside_world(options, device);
    if (!world) {
        return report_user_error(kCommand, world.error());
    }
    std::fflush(stdout);
    if (const auto error = (*session)->start()) {
        return report_user_error(kCommand, error->message);
    }
    const core::TimePoint started = device.loop().now();
    if (run_until_done(device.loop(), options.duration) == RunEnd::Interrupted) {
        fmt::print("interrupted\n");
    }
    fmt::print("served {} in real time\n",
               core::format_duration(std::chrono::round<std::chrono::milliseconds>(
                   device.loop().now() - started)));
    return (*session)->finish(kCommand);
}

} // namespace

void add_serve_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<ServeOptions>();
    CLI::App* command = app.add_subcommand(
        "serve", "Run the EPOS P in real time with its CAN bus open to outside tools and drives");
    add_session_options(*command, options->session, false);
    command->add_option("--socketcand", options->socketcand,
                        "Serve port 2 by the socketcand protocol on HOST:PORT "
                        "(e.g. 127.0.0.1:29536; port 0 picks a free one)");
    command->add_option("--socketcan", options->socketcan,
                        "Bridge a Linux CAN interface (e.g. can0) onto port 2");
    add_duration_option(*command, "--for", options->duration,
                        "Stop after DURATION (otherwise at SIGINT/SIGTERM)");
    command->callback([options, &exit_code] { exit_code = serve(*options); });
}

} // namespace eposp::device::cli
