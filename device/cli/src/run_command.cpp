// `eposp run app.epx|FILES… [--for 10s] [--network net.yaml] [--trace axes.csv]
// [--can-log bus.log] [--pcap bus.pcap] [--watch PATH]…
// [--ns-per-instruction N] [--retain FILE --start warm] [--engine interpreter]`: runs a program on
// the EPOS P in virtual time (with the network of the file: slaves booted at the start) and
// prints the boot report, each task's statistics, the errors raised and the watched variables.
#include "commands.hpp"
#include "eposp/can/candump_log_writer.hpp"
#include "eposp/can/pcap_writer.hpp"
#include "eposp/device/axis_trace.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/device/trace_files.hpp"
#include "eposp/manager/boot_error.hpp"
#include "options.hpp"
#include "program_input.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <optional>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kCommand = "run";
constexpr core::Duration kDefaultDuration = std::chrono::seconds(10);

struct RunOptions {
    std::vector<std::string> paths;
    std::optional<core::Duration> duration;
    std::vector<std::string> watch;
    std::uint64_t ns_per_instruction = 0;
    std::uint64_t watchdog = vm::RuntimeConfig{}.watchdog_instructions;
    std::optional<std::string> retain_file;
    std::string start = "cold";
    vm::Engine engine = vm::default_engine();
    std::optional<std::string> network;
    std::optional<std::string> trace;
    std::optional<std::string> can_log;
    std::optional<std::string> pcap;
};

constexpr core::Duration kTracePeriodWithoutSync = std::chrono::milliseconds(1);

// A file the run writes must not be one it reads: a typo would destroy the program or the network.
std::optional<std::string> overwrites_an_input(const RunOptions& options) {
    std::vector<std::string> inputs = options.paths;
    if (options.network) {
        inputs.push_back(*options.network);
    }
    if (options.retain_file) {
        inputs.push_back(*options.retain_file);
    }
    const std::pair<const char*, const std::optional<std::string>*> outputs[] = {
        {"--trace", &options.trace}, {"--can-log", &options.can_log}, {"--pcap", &options.pcap}};
    std::vector<std::string> written;
    for (const auto& [option, path] : outputs) {
        if (!*path) {
            continue;
        }
        for (const std::string& input : inputs) {
            std::error_code error;
            if (std::filesystem::equivalent(**path, input, error)) {
                return fmt::format("{} {} would overwrite the input {}", option, **path, input);
            }
        }
        for (const std::string& other : written) {
            std::error_code error;
            if (other == **path || std::filesystem::equivalent(**path, other, error)) {
                return fmt::format("{} {}: that file is written twice", option, **path);
            }
        }
        written.push_back(**path);
    }
    return std::nullopt;
}

// The traces the options ask for: the axes of the simulated drives, both buses in the candump
// log, the CAN bus (port 2) in the pcap.
struct RunTraces {
    TraceFiles buses;
    std::unique_ptr<AxisTrace> axes;
};

core::Result<std::unique_ptr<RunTraces>> open_traces(const RunOptions& options, EposP& device,
                                                     const std::optional<NetworkFile>& network) {
    auto traces = std::make_unique<RunTraces>();
    if (options.can_log) {
        if (auto error = traces->buses.add<can::CandumpLogWriter>(
                *options.can_log, {&device.internal_bus(), &device.external_bus()})) {
            return core::Error{fmt::format("--can-log: {}", *error)};
        }
    }
    if (options.pcap) {
        if (auto error =
                traces->buses.add<can::PcapWriter>(*options.pcap, {&device.external_bus()})) {
            return core::Error{fmt::format("--pcap: {}", *error)};
        }
    }
    if (options.trace) {
        auto output = can::TraceOutput::create(*options.trace);
        if (!output) {
            return core::Error{fmt::format("--trace: {}", output.error())};
        }
        const core::Duration period = network && network->sync_period
                                          ? *network->sync_period
                                          : kTracePeriodWithoutSync;
        traces->axes = std::make_unique<AxisTrace>(device.loop(), std::move(*output),
                                                   device.simulated_axes(), period);
    }
    return traces;
}

std::string statistics_line(const vm::TaskStatistics& s, std::uint64_t ns_per_instruction) {
    // Without a cost model every cycle takes no time: execution times, jitter and overruns
    // would all be 0, which says nothing about the program.
    if (ns_per_instruction == 0) {
        return fmt::format("{} instructions in the last cycle; execution time not modelled "
                           "(--ns-per-instruction N gives each instruction N ns)",
                           s.instructions_last);
    }
    return fmt::format("execution last {} min {} avg {} max {}, jitter last {} max {}, "
                       "{} overruns, {} instructions in the last cycle",
                       core::format_duration(s.execution_last),
                       core::format_duration(s.execution_min),
                       core::format_duration(s.execution_average()),
                       core::format_duration(s.execution_max), core::format_duration(s.jitter_last),
                       core::format_duration(s.jitter_max), s.overruns, s.instructions_last);
}

void print_task_summary(Plc& plc, std::uint64_t ns_per_instruction) {
    const auto& tasks = plc.image().tasks;
    vm::PlcRuntime& runtime = plc.runtime();
    for (std::size_t task = 0; task < tasks.size(); ++task) {
        const vm::Task& spec = tasks[task];
        const vm::TaskStatistics& statistics = runtime.statistics(task);
        const std::string when =
            spec.kind == vm::TaskKind::Cyclic
                ? "every " + core::format_duration(core::Duration(spec.interval_ns))
                : std::string("on its event");
        if (runtime.task_faulted(task)) {
            fmt::print("  {}: stopped after {} cycles: {}\n", spec.name, statistics.cycles,
                       runtime.fault_text(task));
        } else {
            fmt::print("  {}: {} cycles, {} (priority {})\n", spec.name, statistics.cycles, when,
                       spec.priority);
        }
        fmt::print("    {}\n", statistics_line(statistics, ns_per_instruction));
    }
}

void print_errors(const Plc& plc) {
    for (const RaisedError& error : plc.errors()) {
        fmt::print("  error 0x{:04X} at {}: {}\n", error.code,
                   core::format_duration(error.when.time_since_epoch()), error.text);
    }
}

std::optional<vm::StartMode> start_mode(const std::string& name) {
    if (name == "cold") {
        return vm::StartMode::Cold;
    }
    if (name == "warm") {
        return vm::StartMode::Warm;
    }
    if (name == "hot") {
        return vm::StartMode::Hot;
    }
    return std::nullopt;
}

std::string identity_read(const manager::SlaveBootResult& result) {
    std::string text = fmt::format("device type 0x{:08X}", result.device_type);
    const std::pair<canopen::LssPart, std::string_view> parts[] = {
        {canopen::LssPart::VendorId, "vendor"},
        {canopen::LssPart::ProductCode, "product"},
        {canopen::LssPart::RevisionNumber, "revision"},
        {canopen::LssPart::SerialNumber, "serial"}};
    for (const auto& [part, name] : parts) {
        if (const std::uint32_t value = result.identity.part(part); value != 0) {
            text += fmt::format(", {} 0x{:08X}", name, value);
        }
    }
    return text;
}

// Each port with slaves: whether its network started, and each slave's boot.
void print_boot_report(const EposP& device, const NetworkFile& network) {
    for (const std::uint8_t port : {kInternalPort, kExternalPort}) {
        if (std::ranges::none_of(
                network.slaves, [port](const NetworkSlave& slave) { return slave.port == port; })) {
            continue;
        }
        const manager::BootReport& report = device.network(port).report();
        fmt::print("boot-up of port {} ({}): {}\n", port,
                   port == kInternalPort ? "internal" : "CAN",
                   report.network_started ? "network started"
                                          : "held back: a mandatory slave did not boot");
        for (const manager::SlaveBootResult& slave : report.slaves) {
            const std::string when = core::format_duration(slave.finished.time_since_epoch());
            if (slave.error) {
                fmt::print("  node {}: failed at {}: 0x{:04X} {}\n", slave.node, when,
                           static_cast<std::uint16_t>(*slave.error), describe(*slave.error));
            } else {
                fmt::print("  node {}: booted at {}: {}\n", slave.node, when, identity_read(slave));
            }
        }
    }
}

int run_program(const RunOptions& options) {
    if (auto problem = overwrites_an_input(options)) {
        return report_user_error(kCommand, *problem);
    }
    auto image = program_image(options.paths);
    if (!image) {
        return report_user_error(kCommand, image.error());
    }
    vm::RuntimeConfig config;
    config.cost.ns_per_instruction = options.ns_per_instruction;
    config.watchdog_instructions = options.watchdog;
    config.engine = options.engine;
    if (options.retain_file) {
        config.retain_file = *options.retain_file;
    }
    std::optional<NetworkFile> network;
    if (options.network) {
        auto loaded = load_network_file(*options.network);
        if (!loaded) {
            return report_user_error(kCommand, loaded.error());
        }
        network = std::move(*loaded);
    }
    EposPConfig device_config;
    device_config.runtime = std::move(config);
    if (network) {
        device_config.external_bit_rate = network->bit_rate;
        device_config.node_id = network->node_id;
    }
    auto device = std::make_unique<EposP>(std::move(device_config));
    if (network) {
        device->add_network(*network);
    }
    Plc& plc = device->plc();
    if (const auto error = plc.load(std::move(*image))) {
        return report_user_error(kCommand, error->message);
    }
    // Unknown watch paths are found before the run, not after it.
    for (const std::string& path : options.watch) {
        if (const auto value = plc.value_of(path); !value) {
            return report_user_error(kCommand, fmt::format("--watch {}: {}", path, value.error()));
        }
    }
    auto traces = open_traces(options, *device, network);
    if (!traces) {
        return report_user_error(kCommand, traces.error());
    }
    if (const auto error = device->start_program(*start_mode(options.start))) {
        return report_user_error(kCommand, error->message);
    }
    const core::Duration duration = options.duration.value_or(kDefaultDuration);
    device->loop().run_until(device->loop().now() + duration);
    plc.runtime().stop(); // saves the RETAIN variables
    if ((*traces)->axes && !(*traces)->axes->good()) {
        return report_user_error(kCommand, fmt::format("--trace {}: write failed", *options.trace));
    }

    fmt::print("ran {} of virtual time\n", core::format_duration(duration));
    if (network) {
        print_boot_report(*device, *network);
    }
    print_task_summary(plc, options.ns_per_instruction);
    print_errors(plc);
    for (const std::string& path : options.watch) {
        fmt::print("{} = {}\n", path, *plc.value_of(path));
    }
    bool faulted = false;
    for (std::size_t task = 0; task < plc.image().tasks.size(); ++task) {
        faulted = faulted || plc.runtime().task_faulted(task);
    }
    return faulted ? 1 : 0;
}

} // namespace

void add_run_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<RunOptions>();
    CLI::App* command =
        app.add_subcommand("run", "Run a program's tasks in virtual time and print what they did");
    command->add_option("files", options->paths, "One .epx image, or the .st files of one program")
        ->required();
    add_duration_option(*command, "--for", options->duration, "Virtual time to run (default 10s)");
    command->add_option("--watch", options->watch,
                        "Print this variable at the end (e.g. Inst0.counter); repeatable");
    command
        ->add_option("--ns-per-instruction", options->ns_per_instruction,
                     "Virtual time one VM instruction takes (0: cycles take no time and "
                     "their execution time is not modelled)")
        ->capture_default_str();
    command
        ->add_option("--watchdog", options->watchdog,
                     "Instructions one task cycle may execute before it is stopped")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_option("--retain", options->retain_file,
                        "File the RETAIN variables are kept in between runs");
    command->add_option("--start", options->start, "Start mode: cold, warm or hot")
        ->check(CLI::IsMember({"cold", "warm", "hot"}))
        ->capture_default_str();
    command->add_option("--network", options->network,
                        "The CANopen network (YAML, docs/network.md): slaves, checks, axes");
    command->add_option("--trace", options->trace,
                        "Write a CSV of the simulated axes to FILE (docs/eposp.md, \"Axis trace\")");
    command->add_option("--can-log", options->can_log,
                        "Record both CAN buses as a candump -L log to FILE");
    command->add_option("--pcap", options->pcap,
                        "Record the CAN bus of port 2 as a pcap (LINKTYPE_CAN_SOCKETCAN) to FILE");
    add_engine_option(*command, options->engine);
    command->callback([options, &exit_code] { exit_code = run_program(*options); });
}

} // namespace eposp::device::cli
