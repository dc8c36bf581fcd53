// `eposp drive escon2 [--config machine.yaml] [--usb pty|PATH|tcp:ADDR] [--for D]
// [--state-dir DIR]`: one simulated maxon ESCON2 with its USB service port, so that a service
// tool (`eposp od`) configures it as its manual says (docs/escon2.md, docs/service-interface.md).
#include "commands.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/device/escon2_machine.hpp"
#include "eposp/device/run_control.hpp"
#include "eposp/device/service_port.hpp"
#include "eposp/service/link_option.hpp"
#include "eposp/service/open_link.hpp"
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

constexpr std::string_view kDriveEscon2Command = "drive escon2";

struct DriveEscon2Options {
    std::string config; ///< hardware, machine and parameters; the defaults without one
    std::optional<std::string> usb;
    std::optional<core::Duration> duration;
    std::optional<std::string> state_dir;
};

core::Result<std::unique_ptr<ServicePort>>
open_usb_port(core::EventLoop& loop, drives::escon2::Escon2Drive& drive, const std::string& text) {
    auto option = service::parse_link_option(text);
    if (!option) {
        return core::Error{fmt::format("--usb: {}", option.error())};
    }
    service::ServingLinkSettings settings;
    settings.pacing = service::LinkPacing::usb();
    auto link = service::open_serving_link(loop, *option, settings);
    if (!link) {
        return core::Error{fmt::format("--usb: {}", link.error())};
    }
    fmt::print("USB service port: {}\n", link->where);
    return std::make_unique<ServicePort>(loop, drive, std::move(link->link));
}

int run_escon2_drive(const DriveEscon2Options& options) {
    Escon2Machine machine;
    std::vector<std::string> inputs;
    if (!options.config.empty()) {
        if (auto problem = input_file_problem(options.config, "an ESCON2's YAML file")) {
            return report_user_error(kDriveEscon2Command, "--config " + *problem);
        }
        auto loaded = load_escon2_machine(options.config);
        if (!loaded) {
            return report_user_error(kDriveEscon2Command, loaded.error());
        }
        machine = std::move(*loaded);
        inputs.push_back(options.config);
    }
    // The non-volatile memory of 0x1010 / 0x1011 (6.2.5, 6.2.6), kept across runs; the machine
    // file's parameters are written over what it brings at each power-up.
    const auto stored = stored_parameters_file(options.state_dir, "escon2");
    if (!stored) {
        return report_user_error(kDriveEscon2Command, stored.error());
    }
    if (auto problem = output_file_problem({"--state-dir", *stored, OutputKind::ParameterFile},
                                           inputs, false)) {
        return report_user_error(kDriveEscon2Command, *problem);
    }
    drives::escon2::Escon2DictionaryConfig dictionary;
    dictionary.parameter_file = *stored;
    // --for alone runs in virtual time, at once; a host on the USB link lives in wall time.
    const bool virtual_time = options.duration && !options.usb;
    core::EventLoop loop(virtual_time ? core::Pace::Virtual : core::Pace::RealTime);
    auto powered_up = start_escon2(loop, machine, std::move(dictionary));
    if (!powered_up) {
        return report_user_error(kDriveEscon2Command, "--config " + powered_up.error());
    }
    const std::unique_ptr<drives::escon2::Escon2Drive> drive = std::move(*powered_up);
    std::unique_ptr<ServicePort> usb;
    if (options.usb) {
        auto port = open_usb_port(loop, *drive, *options.usb);
        if (!port) {
            return report_user_error(kDriveEscon2Command, port.error());
        }
        usb = std::move(*port);
    }
    const auto& hardware = drives::escon2::hardware_data(machine.hardware);
    fmt::print("escon2: {} in {} time\n", hardware.product_name, virtual_time ? "virtual" : "real");
    std::fflush(stdout);

    const core::TimePoint started = loop.now();
    if (run_until_done(loop, options.duration) == RunEnd::Interrupted) {
        fmt::print("interrupted\n");
    }
    fmt::print(
        "escon2: stopped in {} after {}, velocity actual value {}\n",
        drives::motion::to_string(drive->state()),
        core::format_duration(std::chrono::round<std::chrono::milliseconds>(loop.now() - started)),
        drive->objects().get_as<std::int32_t>(0x606C, 0));
    if (usb) {
        const ServicePortCounters counters = usb->counters();
        fmt::print("usb: {} requests, {} answers, {} frame errors, {} hosts hung up\n",
                   counters.requests, counters.answers, counters.frame_errors, counters.hang_ups);
    }
    usb.reset(); // before the drive it serves
    return 0;
}

} // namespace

void add_drive_escon2_command(CLI::App& drive, int& exit_code) {
    auto options = std::make_shared<DriveEscon2Options>();
    CLI::App* escon2 = drive.add_subcommand(
        "escon2", "A simulated maxon ESCON2 servo controller with its USB service port (real time "
                  "until SIGINT, or --for in virtual time)");
    escon2->add_option("--config", options->config,
                       "YAML file of the ESCON2: hardware, plant (an axis file) and parameters, "
                       "as a network file's escon2 entry without its name (docs/escon2.md)");
    escon2->add_option("--usb", options->usb,
                       "Serve the USB port (maxon serial v2): pty (a new pseudo-terminal), a "
                       "serial device PATH, or tcp:ADDR");
    add_state_dir_option(*escon2, options->state_dir, "escon2");
    add_duration_option(*escon2, "--for", options->duration,
                        "Run for DURATION in virtual time (in real time with --usb); otherwise "
                        "in real time until SIGINT/SIGTERM");
    escon2->callback([options, &exit_code] { exit_code = run_escon2_drive(*options); });
}

} // namespace eposp::device::cli
