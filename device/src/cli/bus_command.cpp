// `eposp bus`: hosts a simulated CAN bus that outside tools join over socketcand, optionally
// bridged to a real SocketCAN interface, fed from a candump log and recorded to traces.
#include "commands.hpp"
#include "eposp/canmaster/can/bus_recorder.hpp"
#include "eposp/canmaster/can/candump_log_reader.hpp"
#include "eposp/canmaster/can/candump_log_writer.hpp"
#include "eposp/canmaster/can/candump_replay.hpp"
#include "eposp/canmaster/can/pcap_writer.hpp"
#include "eposp/canmaster/can/port_bridge.hpp"
#include "eposp/canmaster/can/socketcan_port.hpp"
#include "eposp/canmaster/can/socketcand_server.hpp"
#include "eposp/canmaster/can/trace_clock.hpp"
#include "eposp/canmaster/can/virtual_bus.hpp"
#include "options.hpp"
#include "run_control.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <optional>
#include <vector>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kCommand = "bus";

// CiA 301 table 2: the bit rates a CANopen network runs at.
constexpr std::array<std::uint32_t, 8> kCiaBitrates{10'000,  20'000,  50'000,  125'000,
                                                    250'000, 500'000, 800'000, 1'000'000};

struct BusOptions {
    std::string name = "can0";
    std::uint32_t bitrate = 1'000'000;
    std::optional<std::string> socketcand;
    std::optional<std::string> socketcan;
    std::optional<std::string> log;
    std::optional<std::string> pcap;
    std::optional<std::string> replay;
    std::optional<core::Duration> duration;
    bool virtual_time = false;
};

// The traces a run writes, each recording the bus until the run ends.
class Recording {
public:
    Recording(can::VirtualBus& bus, can::TraceClock clock) : bus_(bus), clock_(clock) {}

    template <typename Writer>
    std::optional<std::string> add(const std::string& path) {
        auto output = can::TraceOutput::create(path);
        if (!output) {
            return output.error();
        }
        sinks_.push_back(std::make_unique<Writer>(std::move(*output)));
        recorders_.push_back(std::make_unique<can::BusRecorder>(bus_, *sinks_.back(), clock_));
        return std::nullopt;
    }

private:
    can::VirtualBus& bus_;
    can::TraceClock clock_;
    std::vector<std::unique_ptr<can::TraceSink>> sinks_;
    std::vector<std::unique_ptr<can::BusRecorder>> recorders_;
};

void print_port(const std::string_view name, const can::PortStatistics& port) {
    fmt::print("  {:<16} tx {:>8}  rx {:>8}  tx-overflows {:>4}  rx-overflows {:>4}  {}\n", name,
               port.tx_frames, port.rx_frames, port.tx_overflows, port.rx_overflows,
               can::to_string(port.state));
}

void print_summary(const can::VirtualBus& bus, const std::vector<const can::VirtualPort*>& ports,
                   const can::SocketcandServer* server) {
    const can::BusStatistics stats = bus.statistics();
    fmt::print("bus {} at {} kbit/s: {:.3f} s, {} frames, {} error frames, {} dropped, {} bits "
               "({} stuff bits), load {:.2f} %\n",
               bus.config().name, bus.config().bitrate / 1000,
               std::chrono::duration<double>(stats.elapsed).count(), stats.frames,
               stats.error_frames, stats.dropped_frames, stats.bits, stats.stuff_bits,
               stats.load() * 100.0);
    for (const can::VirtualPort* port : ports) {
        print_port(port->name(), port->statistics());
    }
    if (server) {
        for (const auto& client : server->clients()) {
            if (client.port) {
                print_port(client.client, *client.port);
            }
        }
    }
}

std::optional<std::string> validate(const BusOptions& options) {
    if (std::ranges::find(kCiaBitrates, options.bitrate) == kCiaBitrates.end()) {
        return fmt::format("--bitrate {} is not a CANopen bit rate (one of {})", options.bitrate,
                           fmt::join(kCiaBitrates, ", "));
    }
    if (options.virtual_time && (options.socketcand || options.socketcan)) {
        return "--virtual runs faster than the wall clock, so outside clients "
               "(--socketcand, --socketcan) cannot take part";
    }
    return std::nullopt;
}

int run_bus(const BusOptions& options) {
    if (auto problem = validate(options)) {
        return report_user_error(kCommand, *problem);
    }
    core::EventLoop loop(options.virtual_time ? core::Pace::Virtual : core::Pace::RealTime);
    can::VirtualBus bus(loop, can::BusConfig{.name = options.name, .bitrate = options.bitrate});
    // A virtual run's traces start at 0 s; a real-time run's show wall-clock times like candump.
    const can::TraceClock clock =
        options.virtual_time
            ? can::TraceClock{}
            : can::TraceClock::aligned(loop.now(), std::chrono::time_point_cast<core::Duration>(
                                                       std::chrono::system_clock::now()));

    Recording recording(bus, clock);
    if (options.log) {
        if (auto problem = recording.add<can::CandumpLogWriter>(*options.log)) {
            return report_user_error(kCommand, *problem);
        }
    }
    if (options.pcap) {
        if (auto problem = recording.add<can::PcapWriter>(*options.pcap)) {
            return report_user_error(kCommand, *problem);
        }
    }

    // The host's own controller takes part like a logging interface on a real bus: it
    // acknowledges frames, so a single client's frames complete instead of raising ACK errors.
    const std::unique_ptr<can::VirtualPort> monitor = bus.connect("monitor");
    std::vector<const can::VirtualPort*> own_ports{monitor.get()};

    std::unique_ptr<can::SocketcandServer> server;
    if (options.socketcand) {
        auto opened = can::SocketcandServer::open(
            bus, {.listen = *options.socketcand, .epoch_offset = clock.epoch_offset()});
        if (!opened) {
            return report_user_error(kCommand, opened.error());
        }
        server = std::move(*opened);
        server->on_client_event([](const can::SocketcandClientEvent& event) {
            if (event.kind == can::SocketcandClientEvent::Kind::Connected) {
                fmt::print("socketcand: {} joined from {}\n", event.client, event.remote);
            } else {
                fmt::print("socketcand: {} left ({})\n", event.client, event.reason);
            }
            std::fflush(stdout);
        });
        fmt::print("socketcand: listening on {} (bus {})\n", server->address(), options.name);
    }

    std::unique_ptr<can::SocketCanPort> socketcan;
    std::unique_ptr<can::VirtualPort> socketcan_side;
    std::unique_ptr<can::PortBridge> bridge;
    if (options.socketcan) {
        auto opened = can::SocketCanPort::open(loop, *options.socketcan);
        if (!opened) {
            return report_user_error(
                kCommand, fmt::format("--socketcan {}: {}", *options.socketcan, opened.error()));
        }
        socketcan = std::move(*opened);
        socketcan_side = bus.connect("socketcan:" + *options.socketcan);
        bridge = std::make_unique<can::PortBridge>(*socketcan_side, *socketcan);
        own_ports.push_back(socketcan_side.get());
        fmt::print("socketcan: {} bridged to bus {}\n", *options.socketcan, options.name);
    }

    std::unique_ptr<can::VirtualPort> replay_port;
    std::unique_ptr<can::CandumpReplay> replay;
    if (options.replay) {
        auto records = can::read_candump_log_file(*options.replay);
        if (!records) {
            return report_user_error(kCommand, records.error());
        }
        replay_port = bus.connect("replay");
        replay = std::make_unique<can::CandumpReplay>(loop, *replay_port, std::move(*records));
        own_ports.push_back(replay_port.get());
    }
    std::fflush(stdout);

    const RunEnd end = run_until_done(loop, options.duration);
    if (end == RunEnd::Interrupted) {
        fmt::print("interrupted\n");
    }
    if (replay) {
        const can::ReplayReport& report = replay->report();
        fmt::print("replay: {} frames sent, {} refused, {} skipped{}\n", report.sent,
                   report.refused, report.skipped, replay->finished() ? "" : " (cut short)");
    }
    print_summary(bus, own_ports, server.get());
    return 0;
}

} // namespace

void add_bus_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<BusOptions>();
    CLI::App* command = app.add_subcommand(
        "bus", "Host a simulated CAN bus that outside tools join (real time unless --virtual)");
    command->add_option("--socketcand", options->socketcand,
                        "Serve the socketcand protocol on HOST:PORT (e.g. 127.0.0.1:29536)");
    command->add_option("--socketcan", options->socketcan,
                        "Bridge a Linux CAN interface (e.g. can0, vcan0) onto the bus");
    command->add_option("--name", options->name, "The bus's interface name")->capture_default_str();
    command->add_option("--bitrate", options->bitrate, "Bit rate in bit/s")->capture_default_str();
    command->add_option("--log", options->log, "Record a candump -L log to FILE");
    command->add_option("--pcap", options->pcap, "Record a pcap (LINKTYPE_CAN_SOCKETCAN) to FILE");
    command->add_option("--replay", options->replay, "Play a candump -L log onto the bus")
        ->check(CLI::ExistingFile);
    add_duration_option(*command, "--for", options->duration,
                        "Stop after DURATION (otherwise at SIGINT/SIGTERM, or when a --virtual "
                        "run has nothing left to do)");
    command->add_flag("--virtual", options->virtual_time,
                      "Run in virtual time, as fast as the CPU allows (no outside clients)");
    command->callback([options, &exit_code] { exit_code = run_bus(*options); });
}

} // namespace eposp::device::cli
