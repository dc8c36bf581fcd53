// `eposp eds epos-p|epos2 [-o FILE]`: the EDS (CiA 306) of a simulated device, for a CANopen
// configuration tool or another master; the files shipped in device/ and drives/epos2/ are its
// output.
#include "commands.hpp"
#include "eposp/core/durable_file.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/drives/epos2/epos2_eds.hpp"
#include "file_checks.hpp"
#include "options.hpp"

#include <fmt/format.h>
#include <memory>
#include <optional>
#include <span>
#include <string>

namespace eposp::device::cli {
namespace {

struct EdsOptions {
    std::string device;
    std::optional<std::string> output;
    bool force = false;
};

int write_eds(const EdsOptions& options) {
    const std::string text = options.device == "epos-p" ? epos_p_eds() : drives::epos2::epos2_eds();
    if (!options.output) {
        fmt::print("{}", text);
        return 0;
    }
    if (auto problem = output_file_problem({"-o", *options.output, OutputKind::DeviceDescription},
                                           {}, options.force)) {
        return report_user_error("eds", *problem);
    }
    const auto bytes = std::as_bytes(std::span(text));
    if (const auto error = core::write_file_durably(
            *options.output, {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()})) {
        return report_user_error("eds", error->message);
    }
    return 0;
}

} // namespace

void add_eds_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<EdsOptions>();
    CLI::App* command = app.add_subcommand(
        "eds", "Write the EDS (CiA 306) of a simulated device: the EPOS P or the EPOS2");
    command->add_option("device", options->device, "epos-p or epos2")
        ->required()
        ->check(CLI::IsMember({"epos-p", "epos2"}));
    command->add_option("-o,--output", options->output, "Write to FILE instead of stdout");
    add_force_option(*command, options->force);
    command->callback([options, &exit_code] { exit_code = write_eds(*options); });
}

} // namespace eposp::device::cli
