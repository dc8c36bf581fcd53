#include "options.hpp"

#include "file_checks.hpp"
#include "terminal_text.hpp"

#include <charconv>
#include <cstdio>
#include <fmt/format.h>
#include <vector>

namespace eposp::device::cli {

int report_user_error(std::string_view command, std::string_view message) {
    // A message located in a file ("machine.yaml:2:1: error: ...") carries its own "error:".
    const bool located = message.find(": error: ") != std::string_view::npos;
    fmt::print(stderr, "eposp {}: {}{}\n", command, located ? "" : "error: ",
               terminal_text(message));
    return 1;
}

CLI::Validator whole_number_in(std::uint64_t lowest, std::uint64_t highest) {
    const std::string range = fmt::format("{}..{}", lowest, highest);
    return CLI::Validator(
        [lowest, highest, range](std::string& input) -> std::string {
            std::uint64_t value = 0;
            const char* end = input.data() + input.size();
            const auto [stop, error] = std::from_chars(input.data(), end, value);
            if (error != std::errc{} || stop != end || value < lowest || value > highest) {
                return fmt::format("'{}' is not a whole number in {}", input, range);
            }
            return {};
        },
        range);
}

CLI::Option* add_duration_option(CLI::App& command, const std::string& name,
                                 std::optional<core::Duration>& target,
                                 const std::string& description) {
    return command
        .add_option_function<std::string>(
            name,
            [&target, name](const std::string& text) {
                target = core::parse_duration(text);
                if (!target) {
                    throw CLI::ValidationError(
                        name, "'" + text + "' is not a duration (examples: 10s, 250ms, 2m)");
                }
            },
            description)
        ->type_name("DURATION");
}

CLI::Option* add_engine_option(CLI::App& command, vm::Engine& target) {
    return command
        .add_option_function<std::string>(
            "--engine",
            [&target](const std::string& name) {
                target = name == "interpreter" ? vm::Engine::Interpreter : vm::Engine::Compiled;
            },
            "What runs the program: compiled (machine code where the build can) or interpreter")
        ->check(CLI::IsMember({"compiled", "interpreter"}))
        ->default_str(target == vm::Engine::Compiled ? "compiled" : "interpreter");
}

void add_hosted_bus_options(CLI::App& command, HostedBusOptions& options) {
    CLI::Option* socketcand =
        command.add_option("--socketcand", options.socketcand,
                           "Serve the socketcand protocol on HOST:PORT (e.g. 127.0.0.1:29536)");
    command
        .add_option("--socketcand-queue", options.socketcand_limits.tx_queue_capacity,
                    "Frames a socketcand client may have waiting for the bus; more are dropped")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 20))
        ->needs(socketcand);
    command
        .add_option("--socketcand-clients", options.socketcand_limits.max_clients,
                    "Connections the socketcand server takes at once")
        ->capture_default_str()
        ->check(CLI::Range(1, 1 << 16))
        ->needs(socketcand);
    command.add_option("--socketcan", options.socketcan,
                       "Bridge a Linux CAN interface (e.g. can0, vcan0) onto the bus");
    CLI::Option* join = command.add_option(
        "--join", options.join,
        "Join the bus that a socketcand server on HOST:PORT serves (e.g. another eposp's "
        "--socketcand), bridged both ways");
    command.add_option("--join-bus", options.join_bus, "The bus to open on the --join server")
        ->capture_default_str()
        ->needs(join);
    command.add_option("--name", options.name, "The bus's interface name")->capture_default_str();
    command.add_option("--bitrate", options.bitrate, "Bit rate in bit/s")->capture_default_str();
    command.add_option("--log", options.log, "Record a candump -L log to FILE");
    command.add_option("--pcap", options.pcap, "Record a pcap (LINKTYPE_CAN_SOCKETCAN) to FILE");
    add_duration_option(command, "--for", options.duration,
                        "Stop after DURATION (otherwise at SIGINT/SIGTERM, or when a --virtual "
                        "run has nothing left to do)");
    command.add_flag("--virtual", options.virtual_time,
                     "Run in virtual time, as fast as the CPU allows (no outside clients)");
    add_force_option(command, options.force);
}

std::optional<std::string> hosted_bus_outputs_problem(const HostedBusOptions& options,
                                                      std::span<const std::string> inputs) {
    std::vector<OutputFile> outputs;
    if (options.log) {
        outputs.push_back({"--log", *options.log, OutputKind::CandumpLog});
    }
    if (options.pcap) {
        outputs.push_back({"--pcap", *options.pcap, OutputKind::Pcap});
    }
    return output_files_problem(outputs, inputs, options.force);
}

} // namespace eposp::device::cli
