// `eposp run app.epx|FILES… [--for 10s] [--watch PATH]…`: runs a program's tasks as its
// configuration declares them, in virtual time, and prints what each task did and the watched
// variables at the end.
#include "commands.hpp"
#include "options.hpp"
#include "plc_session.hpp"
#include "program_input.hpp"

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
};

void print_task_summary(PlcSession& session) {
    const auto& tasks = session.image().tasks;
    for (std::size_t task = 0; task < tasks.size(); ++task) {
        const vm::Task& spec = tasks[task];
        const std::uint64_t cycles = session.scheduler().cycles(task);
        const std::string when =
            spec.kind == vm::TaskKind::Cyclic
                ? "every " + core::format_duration(core::Duration(spec.interval_ns))
                : std::string("on its event");
        if (session.scheduler().faulted(task)) {
            fmt::print("  {}: stopped after {} cycles: {}\n", spec.name, cycles,
                       session.machine().describe_fault(task));
        } else {
            fmt::print("  {}: {} cycles, {} (priority {})\n", spec.name, cycles, when,
                       spec.priority);
        }
    }
}

int run_program(const RunOptions& options) {
    auto image = program_image(options.paths);
    if (!image) {
        return report_user_error(kCommand, image.error());
    }
    auto opened = PlcSession::open(std::move(*image));
    if (!opened) {
        return report_user_error(kCommand, opened.error());
    }
    PlcSession& session = **opened;
    // Unknown watch paths are found before the run, not after it.
    for (const std::string& path : options.watch) {
        if (const auto value = session.value_of(path); !value) {
            return report_user_error(kCommand, fmt::format("--watch {}: {}", path, value.error()));
        }
    }
    bool faulted = false;
    session.scheduler().on_fault([&faulted](std::size_t) { faulted = true; });
    session.scheduler().start();
    const core::Duration duration = options.duration.value_or(kDefaultDuration);
    session.loop().run_until(session.loop().now() + duration);

    fmt::print("ran {} of virtual time\n", core::format_duration(duration));
    print_task_summary(session);
    for (const std::string& path : options.watch) {
        fmt::print("{} = {}\n", path, *session.value_of(path));
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
    command->callback([options, &exit_code] { exit_code = run_program(*options); });
}

} // namespace eposp::device::cli
