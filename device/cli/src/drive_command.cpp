// `eposp drive epos2`: one simulated maxon EPOS2 on a simulated CAN bus, hosted like `eposp bus`
// (socketcand, SocketCAN bridge, traces), so that outside CANopen masters can drive it.
#include "commands.hpp"
#include "eposp/device/hosted_bus.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"
#include "eposp/drives/plant/axis_file.hpp"
#include "file_checks.hpp"
#include "options.hpp"
#include "state_directory.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kDriveCommand = "drive epos2";

struct DriveOptions {
    HostedBusOptions hosting;
    int node_id = 1;
    std::string config; ///< the machine's YAML file; the reference axis without one
    std::optional<std::string> state_dir;
};

int run_drive(const DriveOptions& options) {
    if (options.hosting.virtual_time && !options.hosting.duration) {
        // The drive's control loop never idles: a virtual run needs an end.
        return report_user_error(kDriveCommand, "--virtual needs --for DURATION");
    }
    std::vector<std::string> inputs;
    if (!options.config.empty()) {
        if (auto problem = input_file_problem(options.config, "a machine's YAML file")) {
            return report_user_error(kDriveCommand, "--config " + *problem);
        }
        inputs.push_back(options.config);
    }
    // The non-volatile memory of 0x1010 / 0x1011 (8.2.8, 8.2.9), kept across runs.
    const auto stored =
        stored_parameters_file(options.state_dir, fmt::format("epos2-{}", options.node_id));
    if (!stored) {
        return report_user_error(kDriveCommand, stored.error());
    }
    const std::string& parameter_file = *stored;
    if (auto problem =
            output_file_problem({"--state-dir", parameter_file, OutputKind::ParameterFile}, inputs,
                                options.hosting.force)) {
        return report_user_error(kDriveCommand, *problem);
    }
    inputs.push_back(parameter_file);
    if (auto problem = hosted_bus_outputs_problem(options.hosting, inputs)) {
        return report_user_error(kDriveCommand, *problem);
    }
    if (!drives::epos2::bit_rate_code(options.hosting.bitrate)) {
        return report_user_error(
            kDriveCommand,
            fmt::format("an EPOS2 does not run at {} bit/s (table 8-81: 1000000, 800000, 500000, "
                        "250000, 125000, 50000 or 20000)",
                        options.hosting.bitrate));
    }
    drives::epos2::Epos2DriveConfig config;
    config.dictionary.node_id = static_cast<canopen::NodeId>(options.node_id);
    config.dictionary.bit_rate = options.hosting.bitrate;
    config.dictionary.parameter_file = parameter_file;
    if (!options.config.empty()) {
        auto axis = drives::plant::load_axis_file(options.config);
        if (!axis) {
            return report_user_error(kDriveCommand, axis.error());
        }
        config.axis = std::move(*axis);
    }
    auto hosted = HostedBus::open(options.hosting);
    if (!hosted) {
        return report_user_error(kDriveCommand, hosted.error());
    }
    HostedBus& host = **hosted;

    drives::epos2::Epos2Drive drive(host.loop(),
                                    host.attach(fmt::format("epos2 {}", options.node_id)), config);
    drive.start();
    fmt::print("epos2: node {} on bus {}{}\n", options.node_id, options.hosting.name,
               host.socketcand_address() ? ", socketcand " + *host.socketcand_address() : "");
    std::fflush(stdout);

    const RunEnd end = host.run();
    fmt::print("epos2: node {} stopped in {}\n", options.node_id,
               drives::motion::to_string(drive.state()));
    host.print_summary();
    // A lost --join server ends the run early: the nodes were cut off, which a script must see.
    return end == RunEnd::Lost ? 1 : 0;
}

} // namespace

void add_drive_command(CLI::App& app, int& exit_code) {
    CLI::App* drive = app.add_subcommand("drive", "Run a simulated drive on a CAN bus");
    drive->require_subcommand(1);
    auto options = std::make_shared<DriveOptions>();
    CLI::App* epos2 = drive->add_subcommand(
        "epos2", "A simulated maxon EPOS2 24/5 on a simulated bus that outside tools join (real "
                 "time unless --virtual)");
    epos2->add_option("--node-id", options->node_id, "CANopen node-ID")
        ->check(CLI::Range(1, 127))
        ->capture_default_str();
    epos2->add_option("--config", options->config,
                      "YAML file of the simulated machine: motor, gearhead, encoder, load, power "
                      "stage, gains, switch positions (docs/epos2.md)");
    add_state_dir_option(*epos2, options->state_dir, "epos2-<node-ID>");
    add_hosted_bus_options(*epos2, options->hosting);
    epos2->callback([options, &exit_code] { exit_code = run_drive(*options); });
    add_drive_escon2_command(*drive, exit_code);
}

} // namespace eposp::device::cli
