// `eposp run app.epx|FILES… [--for 10s] [--network net.yaml] [--trace axes.csv]
// [--can-log bus.log] [--pcap bus.pcap] [--watch PATH]… [--ns-per-instruction N]
// [--retain FILE --start warm] [--engine interpreter]`: runs a program on the EPOS P in virtual
// time (with the network of the file: slaves booted at the start) and prints the boot report,
// each task's statistics, the errors raised and the watched variables.
#include "commands.hpp"
#include "device_session.hpp"
#include "exit_codes.hpp"
#include "interruptible_run.hpp"
#include "options.hpp"

#include <fmt/format.h>
#include <memory>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kRunCommand = "run";
constexpr core::Duration kDefaultDuration = std::chrono::seconds(10);
// How often a run looks for Ctrl-C: a few milliseconds of wall time for a networked device.
constexpr core::Duration kInterruptCheck = std::chrono::milliseconds(100);

struct RunOptions {
    SessionOptions session;
    std::optional<core::Duration> duration;
};

int run_program(const RunOptions& options) {
    auto session = DeviceSession::open(options.session, core::Pace::Virtual);
    if (!session) {
        return report_user_error(kRunCommand, session.error());
    }
    EposP& device = (*session)->device();
    if (const auto error = (*session)->start()) {
        return report_user_error(kRunCommand, error->message);
    }
    const core::TimePoint started = device.loop().now();
    const core::Duration duration = options.duration.value_or(kDefaultDuration);
    // Ctrl-C ends a long run early; the summary shows what happened up to then.
    const bool interrupted =
        run_until_interrupted(device.loop(), started + duration, kInterruptCheck);
    if (interrupted) {
        fmt::print("interrupted after {} of virtual time\n",
                   core::format_duration(device.loop().now() - started));
    } else {
        fmt::print("ran {} of virtual time\n", core::format_duration(duration));
    }
    const int exit_code = (*session)->finish(kRunCommand);
    return interrupted ? kExitInterrupted : exit_code;
}

} // namespace

void add_run_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<RunOptions>();
    CLI::App* command =
        app.add_subcommand("run", "Run a program's tasks in virtual time and print what they did");
    add_session_options(*command, options->session, true);
    add_duration_option(*command, "--for", options->duration, "Virtual time to run (default 10s)");
    add_error_format_option(*command, options->session.error_format);
    command->callback([options, &exit_code] { exit_code = run_program(*options); });
}

} // namespace eposp::device::cli
