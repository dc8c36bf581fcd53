// `eposp dcf --network net.yaml [-o DIR]`: the configuration a network file describes, as files
// a CANopen configuration tool reads: the EPOS P's DCF (CiA 306, its dictionary as configured)
// and a concise DCF (CiA 302-3) per slave with the writes its boot-up makes.
#include "commands.hpp"
#include "eposp/canopen/eds_export.hpp"
#include "eposp/core/durable_file.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/manager/concise_dcf.hpp"
#include "file_checks.hpp"
#include "options.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <vector>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kDcfCommand = "dcf";

struct DcfOptions {
    std::string network;
    std::string directory = ".";
    bool force = false;
};

struct DcfFile {
    OutputFile file;
    std::vector<std::uint8_t> bytes;
};

// All are checked before the first is written: a refusal leaves none half replaced.
std::optional<std::string> write_files(const std::vector<DcfFile>& files,
                                       const DcfOptions& options) {
    std::vector<OutputFile> outputs;
    for (const DcfFile& dcf : files) {
        outputs.push_back(dcf.file);
    }
    const std::string inputs[] = {options.network};
    if (auto problem = output_files_problem(outputs, inputs, options.force)) {
        return problem;
    }
    for (const DcfFile& dcf : files) {
        if (auto error = core::write_file_durably(dcf.file.path, dcf.bytes)) {
            return error->message;
        }
        fmt::print("wrote {}\n", dcf.file.path);
    }
    return std::nullopt;
}

int write_dcfs(const DcfOptions& options) {
    if (auto problem = input_file_problem(options.network, "a network file")) {
        return report_user_error(kDcfCommand, "--network " + *problem);
    }
    auto network = load_network_file(options.network);
    if (!network) {
        return report_user_error(kDcfCommand, network.error());
    }
    const std::filesystem::path directory(options.directory);
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory)) {
        return report_user_error(
            kDcfCommand,
            fmt::format("-o {}: not a directory the files can go into", options.directory));
    }
    EposPConfig config;
    config.node_id = network->node_id;
    config.external_bit_rate = network->bit_rate;
    EposP device(config);
    device.add_network(*network);

    const canopen::DeviceCommissioning commissioning{
        .node_id = network->node_id,
        .node_name = "EPOS P",
        .baudrate_kbit = network->bit_rate / 1000,
        .network_name = std::filesystem::path(options.network).stem().string(),
        .canopen_manager = true};
    const std::string dcf =
        canopen::export_dcf(device.objects(), epos_p_device_info(), commissioning);
    std::vector<DcfFile> files{
        {{"-o", (directory / "epos-p.dcf").string(), OutputKind::DeviceDescription},
         {dcf.begin(), dcf.end()}}};
    for (const std::uint8_t port : {kInternalPort, kExternalPort}) {
        for (const manager::SlaveEntry& slave : device.network_list(port).slaves) {
            const auto name = fmt::format(
                "{}-node{}.cdcf", port == kInternalPort ? "internal" : "can", slave.node_id);
            files.push_back({{"-o", (directory / name).string(), OutputKind::ConciseDcf},
                             manager::encode_concise_dcf(slave.configuration)});
        }
    }
    if (auto problem = write_files(files, options)) {
        return report_user_error(kDcfCommand, *problem);
    }
    return 0;
}

} // namespace

void add_dcf_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<DcfOptions>();
    CLI::App* command = app.add_subcommand(
        "dcf", "Write a network's configuration: the EPOS P's DCF and each slave's concise DCF");
    command->add_option("--network", options->network, "The network file (docs/network.md)")
        ->required();
    command->add_option("-o,--output", options->directory, "The directory to write them into")
        ->capture_default_str();
    add_force_option(*command, options->force);
    command->callback([options, &exit_code] { exit_code = write_dcfs(*options); });
}

} // namespace eposp::device::cli
