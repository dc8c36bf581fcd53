#include "eposp/device/hosted_bus.hpp"

#include "eposp/can/candump_log_writer.hpp"
#include "eposp/can/pcap_writer.hpp"
#include "eposp/device/socketcand_hosting.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fmt/format.h>

namespace eposp::device {
namespace {

// CiA 301 table 2: the bit rates a CANopen network runs at.
constexpr std::array<std::uint32_t, 8> kCiaBitrates{10'000,  20'000,  50'000,  125'000,
                                                    250'000, 500'000, 800'000, 1'000'000};

std::optional<std::string> validate(const HostedBusOptions& options) {
    if (std::ranges::find(kCiaBitrates, options.bitrate) == kCiaBitrates.end()) {
        return fmt::format("--bitrate {} is not a CANopen bit rate (one of {})", options.bitrate,
                           fmt::join(kCiaBitrates, ", "));
    }
    if (options.virtual_time && (options.socketcand || options.socketcan || options.join)) {
        return "--virtual runs faster than the wall clock, so outside clients "
               "(--socketcand, --socketcan, --join) cannot take part";
    }
    return std::nullopt;
}

// A virtual run's traces start at 0 s; a real-time run's show wall-clock times like candump.
can::TraceClock trace_clock(const core::EventLoop& loop, bool virtual_time) {
    if (virtual_time) {
        return can::TraceClock{};
    }
    return can::TraceClock::aligned(
        loop.now(), std::chrono::time_point_cast<core::Duration>(std::chrono::system_clock::now()));
}

void print_port_line(std::string_view name, const can::PortStatistics& port,
                     std::string_view note) {
    fmt::print("  {:<16} tx {:>8}  rx {:>8}  tx-overflows {:>4}  rx-overflows {:>4}  {}\n", name,
               port.tx_frames, port.rx_frames, port.tx_overflows, port.rx_overflows, note);
}

void print_port(std::string_view name, const can::PortStatistics& port) {
    print_port_line(name, port, can::to_string(port.state));
}

void print_socketcand_history(const can::io::SocketcandServerStatistics& stats) {
    if (stats.left > 0) {
        const can::PortStatistics left{.tx_frames = stats.left_tx_frames,
                                       .rx_frames = stats.left_rx_frames,
                                       .tx_overflows = stats.left_tx_overflows,
                                       .rx_overflows = stats.left_rx_overflows};
        print_port_line(fmt::format("{} left", stats.left), left,
                        "socketcand clients that left, summed");
    }
    if (stats.dropped > 0) {
        fmt::print("  socketcand: {} connections dropped without opening the bus, {} of them "
                   "beyond --socketcand-clients\n",
                   stats.dropped, stats.turned_away);
    }
}

} // namespace

HostedBus::HostedBus(const HostedBusOptions& options)
    : options_(options), loop_(options.virtual_time ? core::Pace::Virtual : core::Pace::RealTime),
      bus_(loop_, can::BusConfig{.name = options.name, .bitrate = options.bitrate}),
      clock_(trace_clock(loop_, options.virtual_time)),
      traces_(std::make_unique<TraceFiles>(clock_)) {}

HostedBus::~HostedBus() = default;

core::Result<std::unique_ptr<HostedBus>> HostedBus::open(const HostedBusOptions& options) {
    if (auto problem = validate(options)) {
        return core::Error{*problem};
    }
    std::unique_ptr<HostedBus> hosted(new HostedBus(options));
    if (auto problem = hosted->open_outside_world()) {
        return core::Error{*problem};
    }
    return hosted;
}

std::optional<std::string> HostedBus::open_outside_world() {
    if (options_.log) {
        if (auto problem = traces_->add<can::CandumpLogWriter>(*options_.log, {&bus_})) {
            return problem;
        }
    }
    if (options_.pcap) {
        if (auto problem = traces_->add<can::PcapWriter>(*options_.pcap, {&bus_})) {
            return problem;
        }
    }
    attach("monitor");

    if (options_.socketcand) {
        auto opened = serve_socketcand(bus_, *options_.socketcand, clock_.epoch_offset(),
                                       options_.socketcand_limits);
        if (!opened) {
            return opened.error();
        }
        server_ = std::move(*opened);
    }

    if (options_.socketcan) {
        auto opened = can::io::SocketCanPort::open(loop_, *options_.socketcan);
        if (!opened) {
            return fmt::format("--socketcan {}: {}", *options_.socketcan, opened.error());
        }
        socketcan_ = std::move(*opened);
        bridge_ = std::make_unique<can::PortBridge>(
            attach_gateway("socketcan:" + *options_.socketcan), *socketcan_);
        fmt::print("socketcan: {} bridged to bus {}\n", *options_.socketcan, options_.name);
    }

    if (options_.join) {
        if (auto problem = join_server()) {
            return problem;
        }
    }
    std::fflush(stdout);
    return std::nullopt;
}

std::optional<std::string> HostedBus::join_server() {
    const std::string& address = *options_.join;
    auto opened = can::io::SocketcandClientPort::open(loop_, address, options_.join_bus);
    if (!opened) {
        return fmt::format("--join {}: {}", address, opened.error());
    }
    joined_ = std::move(*opened);
    // Bridged at once: what the bus sends meanwhile waits in the port until raw mode is on.
    join_bridge_ = std::make_unique<can::PortBridge>(attach_gateway("join:" + address), *joined_);

    // Nothing else runs yet, so the loop is run here until the server has answered; the port
    // gives up by itself when it does not (its handshake timeout).
    using Event = can::io::SocketcandClientPort::Event;
    joined_->on_event([this](const Event& event) {
        if (event.kind != Event::Kind::ServerError) {
            loop_.stop();
        }
    });
    constexpr auto kLongestHandshake = std::chrono::seconds(30);
    loop_.run_for(kLongestHandshake);
    if (!joined_->connected()) {
        const std::string& failure = joined_->failure();
        return fmt::format("--join {}: {}", address,
                           failure.empty() ? "no answer from the server" : failure);
    }
    // Without the server the host's nodes talk to nobody: the run ends, saying why.
    joined_->on_event([this](const Event& event) {
        fmt::print(stderr, "join: {}\n", event.text);
        std::fflush(stderr);
        if (event.kind == Event::Kind::Failed) {
            join_lost_ = true;
            loop_.stop();
        }
    });
    fmt::print("join: bus {} of {} bridged to bus {}\n", options_.join_bus, address, options_.name);
    return std::nullopt;
}

std::optional<std::string> HostedBus::socketcand_address() const {
    if (!server_) {
        return std::nullopt;
    }
    return server_->address();
}

can::VirtualPort& HostedBus::attach(const std::string& name) {
    own_ports_.push_back(bus_.connect(name));
    return *own_ports_.back();
}

can::VirtualPort& HostedBus::attach_gateway(const std::string& name) {
    own_ports_.push_back(bus_.connect(name, can::kGatewayTxQueueCapacity));
    return *own_ports_.back();
}

RunEnd HostedBus::run() {
    std::fflush(stdout);
    const RunEnd end = run_until_done(loop_, options_.duration);
    if (join_lost_) {
        return RunEnd::Lost;
    }
    if (end == RunEnd::Interrupted) {
        fmt::print("interrupted\n");
    }
    return end;
}

void HostedBus::print_summary() const {
    const can::BusStatistics stats = bus_.statistics();
    fmt::print("bus {} at {} kbit/s: {:.3f} s, {} frames, {} error frames, {} dropped, {} bits "
               "({} stuff bits), load {:.2f} %\n",
               bus_.config().name, bus_.config().bitrate / 1000,
               std::chrono::duration<double>(stats.elapsed).count(), stats.frames,
               stats.error_frames, stats.dropped_frames, stats.bits, stats.stuff_bits,
               stats.load() * 100.0);
    for (const auto& port : own_ports_) {
        print_port(port->name(), port->statistics());
    }
    if (server_) {
        for (const auto& client : server_->clients()) {
            if (client.port) {
                print_port(client.client, *client.port);
            }
        }
        print_socketcand_history(server_->statistics());
    }
}

} // namespace eposp::device
