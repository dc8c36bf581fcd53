// `eposp drive epos2`: one simulated maxon EPOS2 on a simulated CAN bus that outside tools join
// over socketcand, in real time (or --virtual for a bounded run).
//
// The bus is hosted here with the socketcand server directly; once the bus-hosting component of
// `eposp node` (HostedBus, branch eposp-node) is on main, open_bus() is replaced by it and the
// drive gains its options (--socketcan, --log, --pcap, --name, --bitrate).
#include "commands.hpp"
#include "eposp/canmaster/can/socketcand_server.hpp"
#include "eposp/canmaster/can/virtual_bus.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"
#include "options.hpp"
#include "run_control.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <optional>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kCommand = "drive epos2";

struct DriveOptions {
    int node_id = 1;
    std::optional<std::string> socketcand;
    std::optional<core::Duration> duration;
    bool virtual_time = false;
};

std::optional<std::string> validate(const DriveOptions& options) {
    if (options.virtual_time && options.socketcand) {
        return "--virtual runs faster than the wall clock, so outside clients (--socketcand) "
               "cannot take part";
    }
    if (options.virtual_time && !options.duration) {
        // The drive's control loop never idles: a virtual run needs an end.
        return "--virtual needs --for DURATION";
    }
    return std::nullopt;
}

int run_drive(const DriveOptions& options) {
    if (auto problem = validate(options)) {
        return report_user_error(kCommand, *problem);
    }
    core::EventLoop loop(options.virtual_time ? core::Pace::Virtual : core::Pace::RealTime);
    can::VirtualBus bus(loop);
    std::unique_ptr<can::SocketcandServer> server;
    if (options.socketcand) {
        auto opened = can::SocketcandServer::open(bus, {.listen = *options.socketcand});
        if (!opened) {
            return report_user_error(kCommand, opened.error());
        }
        server = std::move(*opened);
        fmt::print("socketcand: listening on {}\n", server->address());
    }
    const std::unique_ptr<can::VirtualPort> port = bus.connect("epos2");
    drives::epos2::Epos2DriveConfig config;
    config.dictionary.node_id = static_cast<canopen::NodeId>(options.node_id);
    drives::epos2::Epos2Drive drive(loop, *port, config);
    drive.start();
    fmt::print("epos2: node {} on the bus\n", options.node_id);
    std::fflush(stdout);

    if (run_until_done(loop, options.duration) == RunEnd::Interrupted) {
        fmt::print("interrupted\n");
    }
    fmt::print("epos2: node {} stopped in {}\n", options.node_id,
               drives::motion::to_string(drive.state()));
    return 0;
}

} // namespace

void add_drive_command(CLI::App& app, int& exit_code) {
    CLI::App* drive = app.add_subcommand("drive", "Run a simulated drive on a CAN bus");
    drive->require_subcommand(1);
    auto options = std::make_shared<DriveOptions>();
    CLI::App* epos2 =
        drive->add_subcommand("epos2", "A simulated maxon EPOS2 24/5 (real time unless --virtual)");
    epos2->add_option("--node-id", options->node_id, "CANopen node-ID")
        ->check(CLI::Range(1, 127))
        ->capture_default_str();
    epos2->add_option("--socketcand", options->socketcand,
                      "Serve the socketcand protocol on HOST:PORT (e.g. 127.0.0.1:29536)");
    add_duration_option(*epos2, "--for", options->duration,
                        "Stop after DURATION (otherwise at SIGINT/SIGTERM)");
    epos2->add_flag("--virtual", options->virtual_time,
                    "Run in virtual time, as fast as the CPU allows (needs --for)");
    epos2->callback([options, &exit_code] { exit_code = run_drive(*options); });
}

} // namespace eposp::device::cli
