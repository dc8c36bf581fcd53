#include "device_session.hpp"

#include "eposp/can/candump_log_writer.hpp"
#include "eposp/can/pcap_writer.hpp"
#include "eposp/device/axis_trace.hpp"
#include "eposp/device/trace_files.hpp"
#include "eposp/manager/boot_error.hpp"
#include "exit_codes.hpp"
#include "file_checks.hpp"
#include "options.hpp"
#include "program_input.hpp"
#include "state_directory.hpp"
#include "terminal_text.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <tuple>
#include <vector>

namespace eposp::device::cli {
namespace {

constexpr core::Duration kTracePeriodWithoutSync = std::chrono::milliseconds(1);
// A second per instruction is slower than any controller; the bounds keep the cost of a cycle
// (instructions times cost) within the virtual clock's 64-bit nanoseconds.
constexpr std::uint64_t kMaxNsPerInstruction = 1'000'000'000;
constexpr std::uint64_t kMaxWatchdog = 1'000'000'000'000;

bool network_has_events(const std::optional<NetworkFile>& network) {
    return network && !network->events.empty();
}

// A file the run writes must not be one it reads (a typo would destroy the program or the
// network), nor an existing file of another kind.
std::optional<std::string> output_problem(const SessionOptions& options) {
    std::vector<std::string> inputs = options.paths;
    if (options.network) {
        inputs.push_back(*options.network);
    }
    std::vector<OutputFile> outputs;
    const std::tuple<const char*, const std::optional<std::string>*, OutputKind> written[] = {
        {"--retain", &options.retain_file, OutputKind::RetainStore},
        {"--trace", &options.trace, OutputKind::AxisTrace},
        {"--can-log", &options.can_log, OutputKind::CandumpLog},
        {"--pcap", &options.pcap, OutputKind::Pcap}};
    for (const auto& [option, path, kind] : written) {
        if (*path) {
            outputs.push_back({option, **path, kind});
        }
    }
    return output_files_problem(outputs, inputs, options.force);
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
    if (tasks.empty()) {
        fmt::print("  the program has no task: nothing ran (a CONFIGURATION's TASK runs a "
                   "PROGRAM)\n");
        return;
    }
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
                       terminal_text(runtime.fault_text(task)));
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
                   core::format_duration(error.when.time_since_epoch()), terminal_text(error.text));
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
            // Microseconds: a real-time run's times are not round.
            const std::string when =
                core::format_duration(std::chrono::duration_cast<std::chrono::microseconds>(
                    slave.finished.time_since_epoch()));
            if (slave.error) {
                fmt::print("  node {}: failed at {}: 0x{:04X} {}\n", slave.node, when,
                           static_cast<std::uint16_t>(*slave.error), describe(*slave.error));
            } else {
                fmt::print("  node {}: booted at {}: {}\n", slave.node, when, identity_read(slave));
            }
        }
    }
}

// --state-dir: the EPOS P's non-volatile memory (the program store, the parameter file and,
// unless --retain names another, the retain store), none of them an input.
std::optional<core::Error> use_state_directory(const SessionOptions& options, EposPConfig& config) {
    auto program = stored_program_file(options.state_dir, "epos-p");
    auto parameters = stored_parameters_file(options.state_dir, "epos-p");
    auto retain = stored_retain_file(options.state_dir, "epos-p");
    for (const auto* file : {&program, &parameters, &retain}) {
        if (!*file) {
            return core::Error{"--state-dir: " + file->error()};
        }
    }
    std::vector<OutputFile> outputs{{"--state-dir", *program, OutputKind::ProgramImage},
                                    {"--state-dir", *parameters, OutputKind::ParameterFile}};
    if (!options.retain_file) {
        outputs.push_back({"--state-dir", *retain, OutputKind::RetainStore});
        config.runtime.retain_file = *retain;
    }
    if (auto problem = output_files_problem(outputs, options.paths, options.force)) {
        return core::Error{*problem};
    }
    config.program_file = *program;
    config.parameter_file = *parameters;
    return std::nullopt;
}

bool program_loaded(const Plc& plc) {
    return plc.runtime().state() != vm::ProgramState::NotLoaded;
}

} // namespace

struct DeviceSession::Traces {
    TraceFiles buses;
    std::unique_ptr<AxisTrace> axes;
};

core::Result<std::unique_ptr<DeviceSession::Traces>>
DeviceSession::open_traces(const SessionOptions& options, EposP& device,
                           const std::optional<NetworkFile>& network) {
    auto traces = std::make_unique<DeviceSession::Traces>();
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
        const core::Duration period =
            network && network->sync_period ? *network->sync_period : kTracePeriodWithoutSync;
        traces->axes = std::make_unique<AxisTrace>(device.loop(), std::move(*output),
                                                   device.simulated_axes(), period);
    }
    return traces;
}

void add_session_options(CLI::App& command, SessionOptions& options, bool program_required) {
    auto* files = command.add_option("files", options.paths,
                                     "One .epx image, or the .st files of one program");
    if (program_required) {
        files->required();
    }
    command.add_option("--network", options.network,
                       "The CANopen network (YAML, docs/network.md): slaves, checks, axes");
    // One variable per --watch, so that FILES may follow it.
    command
        .add_option("--watch", options.watch,
                    "Print this variable at the end (e.g. Inst0.counter); repeatable")
        ->allow_extra_args(false);
    command
        .add_option("--ns-per-instruction", options.ns_per_instruction,
                    "Virtual time one VM instruction takes (0: cycles take no time and "
                    "their execution time is not modelled)")
        ->check(whole_number_in(0, kMaxNsPerInstruction))
        ->capture_default_str();
    command
        .add_option("--watchdog", options.watchdog,
                    "Instructions one task cycle may execute before it is stopped")
        ->check(whole_number_in(1, kMaxWatchdog))
        ->capture_default_str();
    command.add_option("--retain", options.retain_file,
                       "File the RETAIN variables are kept in between runs");
    command.add_option("--state-dir", options.state_dir,
                       std::string("Directory of the EPOS P's non-volatile memory: the program "
                                   "downloaded to 0x1F50 (program.epx), the parameters of 0x1010 "
                                   "\"save\" (parameters.bin) and the RETAIN variables "
                                   "(retain.bin, unless --retain); ") +
                           (options.state_by_default ? "default $XDG_STATE_HOME/eposp/epos-p or "
                                                       "~/.local/state/eposp/epos-p"
                                                     : "without it they live in memory only"));
    command.add_option("--start", options.start, "Start mode: cold, warm or hot")
        ->check(CLI::IsMember({"cold", "warm", "hot"}))
        ->capture_default_str();
    command.add_option("--trace", options.trace,
                       "Write a CSV of the simulated axes to FILE (docs/eposp.md, \"Axis trace\")");
    command.add_option("--can-log", options.can_log,
                       "Record both CAN buses as a candump -L log to FILE");
    command.add_option("--pcap", options.pcap,
                       "Record the CAN bus of port 2 as a pcap (LINKTYPE_CAN_SOCKETCAN) to FILE");
    add_engine_option(command, options.engine);
    add_force_option(command, options.force);
}

core::Result<std::unique_ptr<DeviceSession>> DeviceSession::open(const SessionOptions& options,
                                                                 core::Pace pace) {
    if (auto problem = output_problem(options)) {
        return core::Error{*problem};
    }
    if (options.ns_per_instruction >
        static_cast<std::uint64_t>(core::Duration::max().count()) / options.watchdog) {
        return core::Error{fmt::format(
            "--ns-per-instruction {} with --watchdog {}: a cycle could last longer than the "
            "virtual clock counts",
            options.ns_per_instruction, options.watchdog)};
    }
    if (options.network) {
        if (auto problem = input_file_problem(*options.network, "a network file")) {
            return core::Error{"--network " + *problem};
        }
    }
    std::optional<vm::Image> image;
    if (!options.paths.empty()) {
        auto compiled = program_image(options.paths, options.error_format);
        if (!compiled) {
            return core::Error{compiled.error()};
        }
        image = std::move(*compiled);
    }
    std::optional<NetworkFile> network;
    if (options.network) {
        auto loaded = load_network_file(*options.network);
        if (!loaded) {
            return core::Error{loaded.error()};
        }
        network = std::move(*loaded);
    }
    EposPConfig config;
    config.pace = pace;
    config.runtime.cost.ns_per_instruction = options.ns_per_instruction;
    config.runtime.watchdog_instructions = options.watchdog;
    config.runtime.engine = options.engine;
    if (options.retain_file) {
        config.runtime.retain_file = *options.retain_file;
    }
    if (network) {
        config.external_bit_rate = network->bit_rate;
        config.node_id = network->node_id;
    }
    if (options.state_dir || options.state_by_default) {
        if (auto error = use_state_directory(options, config)) {
            return *error;
        }
    }
    auto device = std::make_unique<EposP>(std::move(config));
    if (network) {
        device->add_network(*network);
    }
    std::unique_ptr<DeviceSession> session(
        new DeviceSession(options, std::move(network), std::move(device)));
    Plc& plc = session->device_->plc();
    if (image) {
        if (const auto error = plc.load(std::move(*image))) {
            return *error;
        }
        session->has_program_ = true;
    }
    // The program of the command line or the one stored in --state-dir.
    if (network_has_events(session->network_) && !program_loaded(plc)) {
        return core::Error{"the network file's events release tasks of a program: give one"};
    }
    if (session->network_) {
        for (const EventBinding& event : session->network_->events) {
            if (auto error = session->device_->bind_event(event)) {
                return *error;
            }
        }
    }
    // Unknown watch paths are found before the run, not after it.
    for (const std::string& path : options.watch) {
        if (const auto value = plc.value_of(path); !value) {
            return core::Error{fmt::format("--watch {}: {}", path, value.error())};
        }
    }
    auto traces = open_traces(options, *session->device_, session->network_);
    if (!traces) {
        return core::Error{traces.error()};
    }
    session->traces_ = std::move(*traces);
    return session;
}

DeviceSession::DeviceSession(const SessionOptions& options, std::optional<NetworkFile> network,
                             std::unique_ptr<EposP> device)
    : options_(options), network_(std::move(network)), device_(std::move(device)) {}

DeviceSession::~DeviceSession() = default;

std::optional<core::Error> DeviceSession::start() {
    if (has_program_) {
        return device_->start_program(*start_mode(options_.start));
    }
    if (const std::string& refused = device_->program_refusal(); !refused.empty()) {
        fmt::print("no program: {}\n", terminal_text(refused));
    }
    if (auto error = device_->start_stored_program()) {
        return error;
    }
    if (device_->plc().runtime().state() != vm::ProgramState::Running) {
        device_->boot_networks();
    }
    return std::nullopt;
}

int DeviceSession::finish(std::string_view command) {
    Plc& plc = device_->plc();
    // The program of the command line, the stored one or one a service tool downloaded.
    const bool loaded = program_loaded(plc);
    if (loaded) {
        plc.runtime().stop(); // saves the RETAIN variables
    }
    if (network_) {
        print_boot_report(*device_, *network_);
    }
    bool failed = false;
    if (loaded) {
        print_task_summary(plc, options_.ns_per_instruction);
        print_errors(plc);
        for (const std::string& path : options_.watch) {
            const auto value = plc.value_of(path); // a downloaded program may lack it
            fmt::print("{} = {}\n", path, terminal_text(value ? *value : value.error()));
        }
        // Every fault stops its task and raises an error too: overruns, retain failures and
        // faults all end here.
        failed = !plc.errors().empty();
        for (std::size_t task = 0; task < plc.image().tasks.size(); ++task) {
            failed = failed || plc.runtime().task_faulted(task);
        }
    }
    if (traces_->axes && !traces_->axes->good()) {
        report_user_error(command, fmt::format("--trace {}: write failed", *options_.trace));
        failed = true;
    }
    return failed ? kExitDeviceErrors : kExitSuccess;
}

} // namespace eposp::device::cli
