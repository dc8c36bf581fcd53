// `eposp bench FILES… [--scans N] [--engine interpreter]`: N scans of a program back to back on the
// virtual clock (so TON sees each task interval pass per scan), timed on the wall clock; prints the
// program's global variables and the microseconds per scan, the figure the VM is judged by.
#include "commands.hpp"
#include "eposp/device/plc.hpp"
#include "exit_codes.hpp"
#include "interruptible_run.hpp"
#include "options.hpp"
#include "program_input.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fmt/format.h>
#include <memory>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kBenchCommand = "bench";
// Scans between two looks for Ctrl-C.
constexpr std::int64_t kScansPerInterruptCheck = 1'000;

struct BenchOptions {
    std::vector<std::string> paths;
    std::uint64_t scans = 1000;
    vm::Engine engine = vm::default_engine();
};

/// The task that sets the pace: the cyclic task of the highest priority (first in the table
/// among equals).
std::optional<std::size_t> pacing_task(const vm::Image& image) {
    std::optional<std::size_t> best;
    for (std::size_t task = 0; task < image.tasks.size(); ++task) {
        const vm::Task& t = image.tasks[task];
        if (t.kind == vm::TaskKind::Cyclic && t.interval_ns > 0 &&
            (!best || t.priority < image.tasks[*best].priority)) {
            best = task;
        }
    }
    return best;
}

/// A configuration's global (`Config0.result`): a path whose first name is not itself a variable,
/// as a program instance (`Inst0`, with `Inst0.x` below it) is.
bool is_configuration_global(const vm::Image& image, const vm::Symbol& symbol) {
    const auto dot = symbol.path.find('.');
    if (dot == std::string::npos) {
        return false;
    }
    const std::string_view owner = std::string_view(symbol.path).substr(0, dot);
    return std::none_of(image.symbols.begin(), image.symbols.end(),
                        [owner](const vm::Symbol& other) { return other.path == owner; });
}

/// Reals with six decimals, the form of the expected-results table; other types as literals.
std::string bench_value(Plc& plc, const vm::Symbol& symbol) {
    const vm::TypeDescriptor& type = plc.image().types.at(symbol.type);
    const auto bytes = plc.runtime().memory().subspan(symbol.offset);
    if (type.kind == vm::TypeKind::Elementary && type.scalar == vm::Scalar::F64) {
        double value;
        std::memcpy(&value, bytes.data(), sizeof value);
        return fmt::format("{:.6f}", value);
    }
    if (type.kind == vm::TypeKind::Elementary && type.scalar == vm::Scalar::F32) {
        float value;
        std::memcpy(&value, bytes.data(), sizeof value);
        return fmt::format("{:.6f}", value);
    }
    return *plc.value_of(symbol.path);
}

int run_bench(const BenchOptions& options) {
    auto image = program_image(options.paths);
    if (!image) {
        return report_user_error(kBenchCommand, image.error());
    }
    const auto pacing = pacing_task(*image);
    if (!pacing) {
        return report_user_error(kBenchCommand, "the program has no cyclic task to scan");
    }
    vm::RuntimeConfig config;
    config.engine = options.engine;
    // The PLC alone: the scans' wall time is the program's, not a drive simulation's too.
    core::EventLoop loop(core::Pace::Virtual);
    Plc plc(loop, std::move(config));
    if (const auto error = plc.load(std::move(*image))) {
        return report_user_error(kBenchCommand, error->message);
    }
    const core::Duration interval(plc.image().tasks[*pacing].interval_ns);
    // The first scan runs at start(), the n-th one (n - 1) intervals later.
    const core::TimePoint last_scan =
        loop.now() + interval * static_cast<core::Duration::rep>(options.scans - 1);

    const auto wall_start = std::chrono::steady_clock::now();
    if (const auto error = plc.runtime().start(vm::StartMode::Cold)) {
        return report_user_error(kBenchCommand, error->message);
    }
    // Ctrl-C ends a long benchmark early; the figures are those of the scans done by then.
    const bool interrupted =
        run_until_interrupted(loop, last_scan, interval * kScansPerInterruptCheck);
    const std::chrono::duration<double, std::micro> wall =
        std::chrono::steady_clock::now() - wall_start;
    const std::uint64_t scans = plc.runtime().statistics(*pacing).cycles;

    if (plc.runtime().task_faulted(*pacing)) {
        report_user_error(kBenchCommand, plc.runtime().fault_text(*pacing));
        return kExitDeviceErrors; // the program ran into the fault: no figure to give
    }
    for (const vm::Symbol& symbol : plc.image().symbols) {
        if (is_configuration_global(plc.image(), symbol)) {
            fmt::print("{}={} ", symbol.path.substr(symbol.path.find('.') + 1),
                       bench_value(plc, symbol));
        }
    }
    const std::uint64_t timed = interrupted ? std::max<std::uint64_t>(scans, 1) : options.scans;
    fmt::print("us_per_scan={:.3f}\n", wall.count() / static_cast<double>(timed));
    if (interrupted) {
        fmt::print("interrupted after {} of {} scans\n", scans, options.scans);
        return kExitInterrupted;
    }
    return kExitSuccess;
}

} // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* command = app.add_subcommand(
        "bench", "Run N scans of a program back to back and print its globals and µs per scan");
    command->add_option("files", options->paths, "One .epx image, or the .st files of one program")
        ->required();
    command->add_option("--scans", options->scans, "Scans to run")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1'000'000'000}))
        ->capture_default_str();
    add_engine_option(*command, options->engine);
    command->callback([options, &exit_code] { exit_code = run_bench(*options); });
}

} // namespace eposp::device::cli
