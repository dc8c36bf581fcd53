// `eposp node`: a plain CANopen slave built from an EDS file, hosted on a simulated bus that
// outside tools (python-can, CANopen browsers) join over socketcand or SocketCAN.
#include "commands.hpp"
#include "eposp/canopen/eds_import.hpp"
#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/canopen/node.hpp"
#include "eposp/device/hosted_bus.hpp"
#include "file_checks.hpp"
#include "options.hpp"
#include "state_directory.hpp"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kNodeCommand = "node";

struct NodeOptions {
    HostedBusOptions hosting;
    std::string eds;
    unsigned node_id = 0;
    std::optional<std::string> parameter_file;
    std::optional<std::string> state_dir;
};

core::Result<std::string> read_text_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return core::Error{fmt::format("cannot read {}: {}", path, std::strerror(errno))};
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// A sub-object of the dictionary as UNSIGNED32, or `fallback` when the EDS lacks it.
std::uint32_t u32_or(const canopen::ObjectDictionary& od, std::uint16_t index,
                     std::uint8_t sub_index, std::uint32_t fallback) {
    return od.find(index, sub_index) != nullptr ? od.get_as<std::uint32_t>(index, sub_index)
                                                : fallback;
}

/// CiA 306 leaves persistence out of an EDS, so the node decides: 0x1010 "save all parameters"
/// stores every writable entry but the error history and the store / restore commands.
void make_parameters_persistent(canopen::ObjectDictionary& od) {
    constexpr std::uint16_t kStoreParameters = 0x1010;
    constexpr std::uint16_t kRestoreDefaultParameters = 0x1011;
    for (const auto& [index, object] : od.objects()) {
        if (index == canopen::kPreDefinedErrorFieldIndex || index == kStoreParameters ||
            index == kRestoreDefaultParameters) {
            continue;
        }
        for (const auto& [sub_index, sub] : object.subs) {
            od.find(index, sub_index)->persistent = canopen::writable(sub.access);
        }
    }
}

/// The node's configuration beyond the EDS: 0x1000 and 0x1018 come from the EDS where it has
/// them (the node adds only what the dictionary lacks), else from its [DeviceInfo].
canopen::NodeConfig node_config(const NodeOptions& options, const canopen::ImportedEds& eds,
                                const std::string& parameter_file) {
    const canopen::ObjectDictionary& od = eds.dictionary;
    canopen::NodeConfig config;
    config.node_id = static_cast<canopen::NodeId>(options.node_id);
    config.device_type = u32_or(od, canopen::kDeviceTypeIndex, 0, 0);
    config.identity = {
        .vendor_id = u32_or(od, canopen::kIdentityIndex, 1, eds.device.vendor_number),
        .product_code = u32_or(od, canopen::kIdentityIndex, 2, eds.device.product_number),
        .revision_number = u32_or(od, canopen::kIdentityIndex, 3, eds.device.revision_number),
        .serial_number = u32_or(od, canopen::kIdentityIndex, 4, 0),
    };
    config.parameter_file = parameter_file;
    // CiA 305: LSS takes the bit rates the EDS declares. The simulated bus keeps the rate it
    // was opened with (a port has none of its own): a switch to another one is only told.
    config.bit_rates = eds.device.bit_rates();
    config.bit_rate = options.hosting.bitrate;
    config.switch_bit_rate = [node = options.node_id,
                              bus = options.hosting.bitrate](std::uint32_t bit_rate) {
        if (bit_rate != bus) {
            fmt::print("node {}: bit rate {} bit/s by LSS (the simulated bus runs at {} bit/s)\n",
                       node, bit_rate, bus);
        }
    };
    return config;
}

/// --parameter-file, else the parameter file of the node's state directory.
core::Result<std::string> parameter_file(const NodeOptions& options) {
    if (options.parameter_file) {
        return *options.parameter_file;
    }
    return stored_parameters_file(options.state_dir, fmt::format("node-{}", options.node_id));
}

// The EDS is read and the parameter file both read and written: neither may be a trace, and the
// parameter file is replaced only when it is one (file_checks.hpp).
std::optional<std::string> files_problem(const NodeOptions& options,
                                         const std::string& parameter_file) {
    if (auto problem = input_file_problem(options.eds, "an EDS file")) {
        return "--eds " + *problem;
    }
    std::vector<std::string> inputs{options.eds};
    const std::string option = options.parameter_file ? "--parameter-file" : "--state-dir";
    if (auto problem = output_file_problem({option, parameter_file, OutputKind::ParameterFile},
                                           inputs, options.hosting.force)) {
        return problem;
    }
    inputs.push_back(parameter_file);
    return hosted_bus_outputs_problem(options.hosting, inputs);
}

int run_node(const NodeOptions& options) {
    const auto parameters = parameter_file(options);
    if (!parameters) {
        return report_user_error(kNodeCommand, parameters.error());
    }
    if (auto problem = files_problem(options, *parameters)) {
        return report_user_error(kNodeCommand, *problem);
    }
    const auto text = read_text_file(options.eds);
    if (!text) {
        return report_user_error(kNodeCommand, text.error());
    }
    auto eds =
        canopen::import_eds(*text, options.eds, static_cast<canopen::NodeId>(options.node_id));
    if (!eds) {
        return report_user_error(kNodeCommand, eds.error());
    }
    // The import tolerates missing sections; a file without any object is not a device's EDS
    // (CiA 306 4.6.1: [MandatoryObjects] lists at least 0x1000, 0x1001 and 0x1018).
    if (eds->dictionary.objects().empty()) {
        return report_user_error(
            kNodeCommand, fmt::format("{}: lists no object ([MandatoryObjects], [OptionalObjects] and "
                                  "[ManufacturerObjects] are missing or empty)",
                                  options.eds));
    }
    make_parameters_persistent(eds->dictionary);
    auto hosted = HostedBus::open(options.hosting);
    if (!hosted) {
        return report_user_error(kNodeCommand, hosted.error());
    }
    HostedBus& host = **hosted;

    const std::string port_name = fmt::format("node {}", options.node_id);
    canopen::Node node(host.loop(), host.attach(port_name), eds->dictionary,
                       node_config(options, *eds, *parameters));
    const std::string& name =
        eds->device.product_name.empty() ? options.eds : eds->device.product_name;
    fmt::print("node {} ({}) on bus {}{}\n", options.node_id, name, options.hosting.name,
               host.socketcand_address() ? ", socketcand " + *host.socketcand_address() : "");
    node.start();

    const RunEnd end = host.run();
    fmt::print("node {}: {}\n", options.node_id, canopen::to_string(node.nmt_state()));
    host.print_summary();
    // A lost --join server ends the run early: the nodes were cut off, which a script must see.
    return end == RunEnd::Lost ? 1 : 0;
}

} // namespace

void add_node_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<NodeOptions>();
    CLI::App* command = app.add_subcommand(
        "node", "Run a CANopen slave built from an EDS file on a simulated bus that outside "
                "tools join (real time unless --virtual)");
    command->add_option("--eds", options->eds, "The node's electronic data sheet (CiA 306 EDS/DCF)")
        ->required();
    command
        ->add_option("--node-id", options->node_id,
                     fmt::format("The node-ID, 1..{} ($NODEID in the EDS)", canopen::kMaxNodeId))
        ->required()
        ->check(CLI::Range(1U, unsigned{canopen::kMaxNodeId}));
    command->add_option("--parameter-file", options->parameter_file,
                        "Non-volatile memory of 0x1010 store / 0x1011 restore (LSS store "
                        "configuration beside it, FILE.lss); default: in --state-dir");
    add_state_dir_option(*command, options->state_dir, "node-<node-ID>");
    add_hosted_bus_options(*command, options->hosting);
    command->callback([options, &exit_code] { exit_code = run_node(*options); });
}

} // namespace eposp::device::cli
