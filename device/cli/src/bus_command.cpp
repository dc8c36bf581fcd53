// `eposp bus`: hosts a simulated CAN bus that outside tools join over socketcand, optionally
// bridged to a real SocketCAN interface, fed from a candump log and recorded to traces.
#include "commands.hpp"
#include "eposp/can/candump_log_reader.hpp"
#include "eposp/can/candump_replay.hpp"
#include "eposp/device/hosted_bus.hpp"
#include "options.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kBusCommand = "bus";

struct BusOptions {
    HostedBusOptions hosting;
    std::optional<std::string> replay;
};

int run_bus(const BusOptions& options) {
    std::vector<std::string> inputs;
    if (options.replay) {
        inputs.push_back(*options.replay);
    }
    if (auto problem = hosted_bus_outputs_problem(options.hosting, inputs)) {
        return report_user_error(kBusCommand, *problem);
    }
    auto hosted = HostedBus::open(options.hosting);
    if (!hosted) {
        return report_user_error(kBusCommand, hosted.error());
    }
    HostedBus& host = **hosted;

    std::unique_ptr<can::CandumpReplay> replay;
    if (options.replay) {
        auto records = can::read_candump_log_file(*options.replay);
        if (!records) {
            return report_user_error(kBusCommand, records.error());
        }
        // The reader skips lines that are not frames, as canplayer does; a file with no frame
        // at all is another kind of file given by mistake.
        std::error_code error;
        if (records->empty() && std::filesystem::file_size(*options.replay, error) > 0) {
            return report_user_error(kBusCommand,
                                     fmt::format("--replay {}: not a candump -L log (no line like "
                                                 "\"(1.000000) can0 123#DEADBEEF\")",
                                                 *options.replay));
        }
        replay = std::make_unique<can::CandumpReplay>(host.loop(), host.attach("replay"),
                                                      std::move(*records));
    }

    const RunEnd end = host.run();
    if (replay) {
        const can::ReplayReport& report = replay->report();
        fmt::print("replay: {} frames sent, {} refused, {} skipped{}\n", report.sent,
                   report.refused, report.skipped, replay->finished() ? "" : " (cut short)");
    }
    host.print_summary();
    // A lost --join server ends the run early: the nodes were cut off, which a script must see.
    return end == RunEnd::Lost ? 1 : 0;
}

} // namespace

void add_bus_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<BusOptions>();
    CLI::App* command = app.add_subcommand(
        "bus", "Host a simulated CAN bus that outside tools join (real time unless --virtual)");
    add_hosted_bus_options(*command, options->hosting);
    command->add_option("--replay", options->replay, "Play a candump -L log onto the bus")
        ->check(CLI::ExistingFile);
    command->callback([options, &exit_code] { exit_code = run_bus(*options); });
}

} // namespace eposp::device::cli
