// `eposp serve [app.epx|FILES…] [--network net.yaml] [--serial pty|PATH|tcp:ADDR]
// [--usb pty|PATH|tcp:ADDR] [--socketcand HOST:PORT] [--socketcan IF] [--for 10s] [the options
// of run]`: the EPOS P in real time with its service links and its CAN bus (port 2) open to the
// outside: service tools speak maxon's serial protocols on the emulated RS-232 and USB ports
// (docs/service-interface.md); external slaves (`eposp drive epos2 --join`, python-canopen, real
// drives over SocketCAN) take part in its boot-up and control, and CANopen tools reach its own
// SDO server. Without a program the networks boot alone. It runs until --for elapses or SIGINT /
// SIGTERM.
#include "commands.hpp"
#include "device_session.hpp"
#include "eposp/can/io/socketcan_port.hpp"
#include "eposp/can/port_bridge.hpp"
#include "eposp/can/trace_clock.hpp"
#include "eposp/device/run_control.hpp"
#include "eposp/device/service_port.hpp"
#include "eposp/device/socketcand_hosting.hpp"
#include "eposp/service/link_option.hpp"
#include "eposp/service/open_link.hpp"
#include "options.hpp"

#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <tuple>
#include <vector>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kServeCommand = "serve";

struct ServeOptions {
    SessionOptions session;
    std::optional<std::string> socketcand;
    std::optional<std::string> socketcan;
    std::optional<core::Duration> duration;
    std::optional<std::string> serial;
    std::optional<std::string> usb;
    std::optional<std::string> serial_link;
    std::optional<std::string> usb_link;
    std::uint32_t baud = 115200;
    bool no_pacing = false;
};

// Port 2 as the outside world reaches it. Declared after the session, destroyed before it.
struct OutsideWorld {
    std::unique_ptr<can::io::SocketcandServer> server;
    std::unique_ptr<can::io::SocketCanPort> socketcan;
    std::unique_ptr<can::VirtualPort> bridge_port;
    std::unique_ptr<can::PortBridge> bridge;
    std::vector<std::unique_ptr<ServicePort>> service_ports;
};

// The RS-232 or USB port on the link the option names, paced at its line rate.
core::Result<std::unique_ptr<ServicePort>>
open_service_port(EposP& device, ServiceProtocol protocol, const std::string& option_text,
                  const std::optional<std::string>& symlink, const ServeOptions& options) {
    const std::string option_name = protocol == ServiceProtocol::Rs232 ? "--serial" : "--usb";
    auto option = service::parse_link_option(option_text);
    if (!option) {
        return core::Error{fmt::format("{}: {}", option_name, option.error())};
    }
    service::ServingLinkSettings settings;
    settings.pacing = options.no_pacing ? service::LinkPacing::off()
                      : protocol == ServiceProtocol::Rs232
                          ? service::LinkPacing::rs232(options.baud)
                          : service::LinkPacing::usb();
    settings.baud = options.baud;
    if (symlink) {
        settings.symlink = *symlink;
    }
    auto link = service::open_serving_link(device.loop(), *option, settings);
    if (!link) {
        return core::Error{fmt::format("{}: {}", option_name, link.error())};
    }
    fmt::print("{} service port: {}\n", to_string(protocol), link->where);
    return std::make_unique<ServicePort>(device, std::move(link->link), protocol);
}

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
        world.bridge_port =
            bus.connect("socketcan-" + *options.socketcan, can::kGatewayTxQueueCapacity);
        world.bridge = std::make_unique<can::PortBridge>(*world.socketcan, *world.bridge_port);
        fmt::print("socketcan: bridged {} onto bus {}\n", *options.socketcan, bus.config().name);
    }
    for (const auto& [protocol, text, symlink] :
         {std::tuple{ServiceProtocol::Rs232, options.serial, options.serial_link},
          std::tuple{ServiceProtocol::Usb, options.usb, options.usb_link}}) {
        if (!text) {
            continue;
        }
        auto port = open_service_port(device, protocol, *text, symlink, options);
        if (!port) {
            return core::Error{port.error()};
        }
        world.service_ports.push_back(std::move(*port));
    }
    return world;
}

int serve(const ServeOptions& options) {
    auto session = DeviceSession::open(options.session, core::Pace::RealTime);
    if (!session) {
        return report_user_error(kServeCommand, session.error());
    }
    EposP& device = (*session)->device();
    auto world = open_outside_world(options, device);
    if (!world) {
        return report_user_error(kServeCommand, world.error());
    }
    std::fflush(stdout);
    if (const auto error = (*session)->start()) {
        return report_user_error(kServeCommand, error->message);
    }
    const core::TimePoint started = device.loop().now();
    if (run_until_done(device.loop(), options.duration) == RunEnd::Interrupted) {
        fmt::print("interrupted\n");
    }
    fmt::print("served {} in real time\n",
               core::format_duration(
                   std::chrono::round<std::chrono::milliseconds>(device.loop().now() - started)));
    return (*session)->finish(kServeCommand);
}

} // namespace

void add_serve_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<ServeOptions>();
    CLI::App* command = app.add_subcommand(
        "serve", "Run the EPOS P in real time with its CAN bus open to outside tools and drives");
    options->session.state_by_default = true;
    add_session_options(*command, options->session, false);
    command->add_option("--socketcand", options->socketcand,
                        "Serve port 2 by the socketcand protocol on HOST:PORT "
                        "(e.g. 127.0.0.1:29536; port 0 picks a free one)");
    command->add_option("--socketcan", options->socketcan,
                        "Bridge a Linux CAN interface (e.g. can0) onto port 2");
    command->add_option("--serial", options->serial,
                        "Serve the RS-232 port (maxon serial v1): pty (a new pseudo-terminal), "
                        "a serial device PATH, or tcp:ADDR (e.g. tcp:127.0.0.1:0)");
    command->add_option("--usb", options->usb,
                        "Serve the USB port (maxon serial v2): pty, a PATH or tcp:ADDR");
    command
        ->add_option("--serial-link", options->serial_link,
                     "Make a symlink to the RS-232 pseudo-terminal here (e.g. ./ttyEPOSP)")
        ->needs(command->get_option("--serial"));
    command
        ->add_option("--usb-link", options->usb_link,
                     "Make a symlink to the USB pseudo-terminal here")
        ->needs(command->get_option("--usb"));
    command->add_option("--baud", options->baud, "The RS-232 line rate, bit/s")
        ->capture_default_str()
        ->check(CLI::Range(1200U, 4'000'000U));
    command->add_flag("--no-pacing", options->no_pacing,
                      "Send on the service links at once instead of at their line rate");
    add_duration_option(*command, "--for", options->duration,
                        "Stop after DURATION (otherwise at SIGINT/SIGTERM)");
    command->callback([options, &exit_code] { exit_code = serve(*options); });
}

} // namespace eposp::device::cli
