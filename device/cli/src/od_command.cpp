// `eposp od --port PATH|tcp:ADDR read INDEX SUB | write INDEX SUB VALUE | dump`: the object
// dictionary of an EPOS P (or of a node behind its gateway) or of an ESCON2 over its service
// interface, as maxon's tools reach it (docs/service-interface.md, "Clients"). Values up to 4
// bytes go by ReadObject / WriteObject, strings and longer ones by segmented transfer.
#include "commands.hpp"
#include "exit_codes.hpp"
#include "object_value.hpp"
#include "options.hpp"
#include "served_device.hpp"
#include "service_connection.hpp"
#include "terminal_text.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <memory>

namespace eposp::device::cli {
namespace {

constexpr std::string_view kOdCommand = "od";
/// CiA 301: the value is longer than ReadObject's 4 bytes.
constexpr std::uint32_t kLengthTooHigh = 0x06070012;

struct OdOptions {
    ServiceClientOptions link;
    ObjectTargetOptions target;
    std::string index;
    std::string sub_index;
    std::string value;
    std::optional<std::string> type;
};

struct ObjectName {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
};

core::Result<ObjectName> parse_object_name(const OdOptions& options) {
    const auto index = parse_unsigned(options.index, 0xFFFF);
    if (!index) {
        return core::Error{fmt::format("INDEX '{}' is not an object index (0x0000 to 0xFFFF)",
                                       terminal_text(options.index))};
    }
    const auto sub_index = parse_unsigned(options.sub_index, 0xFF);
    if (!sub_index) {
        return core::Error{fmt::format("SUB '{}' is not a sub-index (0 to 255)",
                                       terminal_text(options.sub_index))};
    }
    return ObjectName{static_cast<std::uint16_t>(*index), static_cast<std::uint8_t>(*sub_index)};
}

// --type, or the type the dictionary of the device itself (the EPOS P or an ESCON2: it is asked
// which) gives the object; a node behind the gateway is read as u32 unless told.
service::ClientResult<ValueType> value_type(const OdOptions& options, const ObjectName& name,
                                            ServiceConnection& connection) {
    if (options.type) {
        return *parse_value_type(*options.type);
    }
    if (options.target.node == 0 && options.target.network.value_or(0) == 0) {
        const auto device = identify_device(connection);
        if (!device) {
            return device.error();
        }
        const ServedDictionary dictionary(*device);
        if (const auto* entry = dictionary.objects().find(name.index, name.sub_index)) {
            return value_type_of(entry->type);
        }
    }
    return ValueType::U32;
}

// Reads one object as `type`: by ReadObject when it fits, else by segmented read.
service::ClientResult<std::vector<std::uint8_t>>
read_value(ServiceConnection& connection, const service::ObjectAddress& address, ValueType type) {
    if (!fits_one_request(type)) {
        return connection.read_segmented(address);
    }
    const auto value = connection.read_object(address);
    if (!value) {
        return value.error();
    }
    return std::vector<std::uint8_t>(value->begin(), value->end());
}

int exit_code_for(const ServiceConnection& connection, const service::ClientError& error) {
    if (connection.interrupted()) {
        return kExitInterrupted;
    }
    return report_user_error(kOdCommand, error.message);
}

core::Result<std::unique_ptr<ServiceConnection>> open(const OdOptions& options) {
    return ServiceConnection::open(options.link);
}

bool is_printable(std::span<const std::uint8_t> bytes) {
    return std::ranges::all_of(bytes,
                               [](std::uint8_t byte) { return byte >= 0x20 && byte < 0x7F; });
}

int read_command(const OdOptions& options) {
    const auto name = parse_object_name(options);
    if (!name) {
        return report_user_error(kOdCommand, name.error());
    }
    auto connection = open(options);
    if (!connection) {
        return report_user_error(kOdCommand, connection.error());
    }
    const auto typed = value_type(options, *name, **connection);
    if (!typed) {
        return exit_code_for(**connection, typed.error());
    }
    ValueType type = *typed;
    const auto address = object_address(options.target, name->index, name->sub_index);
    auto value = read_value(**connection, address, type);
    // An object longer than 4 bytes whose type is unknown here (a node's, no --type): read it
    // whole (the ESCON2 says "segmented transfer expected", table 111).
    if (!value && !options.type &&
        (value.error().code == kLengthTooHigh ||
         value.error().code == service::error::kSegmentedTransferExpected)) {
        value = (*connection)->read_segmented(address);
        type = value && is_printable(*value) ? ValueType::Str : ValueType::Hex;
    }
    if (!value) {
        return exit_code_for(**connection, value.error());
    }
    fmt::print("0x{:04X} sub {}: {}\n", name->index, name->sub_index, format_value(type, *value));
    return kExitSuccess;
}

int write_command(const OdOptions& options) {
    const auto name = parse_object_name(options);
    if (!name) {
        return report_user_error(kOdCommand, name.error());
    }
    // With --type a wrong value is refused before the link is opened.
    if (options.type) {
        if (const auto bytes = encode_value(*parse_value_type(*options.type), options.value);
            !bytes) {
            return report_user_error(kOdCommand, fmt::format("VALUE: {}", bytes.error()));
        }
    }
    auto connection = open(options);
    if (!connection) {
        return report_user_error(kOdCommand, connection.error());
    }
    const auto typed = value_type(options, *name, **connection);
    if (!typed) {
        return exit_code_for(**connection, typed.error());
    }
    const ValueType type = *typed;
    const auto bytes = encode_value(type, options.value);
    if (!bytes) {
        return report_user_error(kOdCommand, fmt::format("VALUE: {}", bytes.error()));
    }
    const auto address = object_address(options.target, name->index, name->sub_index);
    service::ClientResult<service::Done> written = service::Done{};
    if (fits_one_request(type)) {
        std::array<std::uint8_t, 4> value{};
        std::copy(bytes->begin(), bytes->end(), value.begin());
        written = (*connection)->write_object(address, value);
    } else {
        written = (*connection)->write_segmented(address, *bytes);
    }
    if (!written) {
        return exit_code_for(**connection, written.error());
    }
    fmt::print("0x{:04X} sub {} := {}\n", name->index, name->sub_index, format_value(type, *bytes));
    return kExitSuccess;
}

// A long DOMAIN (a program image) shows its beginning and its length, so that a row stays a row.
std::string table_value(ValueType type, std::span<const std::uint8_t> value) {
    constexpr std::size_t kShownBytes = 16;
    if (type != ValueType::Hex || value.size() <= kShownBytes) {
        return format_value(type, value);
    }
    return fmt::format("{} ... ({} bytes)", format_value(type, value.first(kShownBytes)),
                       value.size());
}

// Every object of the device's dictionary (the EPOS P's or an ESCON2's), read one by one; a
// refused one shows its error and the table goes on, a device that stops answering ends it.
int dump_command(const OdOptions& options) {
    auto connection = open(options);
    if (!connection) {
        return report_user_error(kOdCommand, connection.error());
    }
    const auto device = identify_device(**connection);
    if (!device) {
        return exit_code_for(**connection, device.error());
    }
    const ServedDictionary dictionary(*device);
    fmt::print("{:<6}  {:>3}  {:<40}  {}\n", "index", "sub", "name", "value");
    std::size_t refused = 0;
    for (const auto& [index, object] : dictionary.objects().objects()) {
        for (const auto& [sub_index, entry] : object.subs) {
            const std::string name =
                object.subs.size() == 1 ? object.name : object.name + ": " + entry.name;
            std::string shown;
            if (!canopen::readable(entry.access)) {
                shown = "(write only)";
            } else {
                const ValueType type = value_type_of(entry.type);
                const auto value =
                    read_value(**connection, object_address({}, index, sub_index), type);
                if (!value && value.error().kind != service::ClientError::Kind::Refused) {
                    return exit_code_for(**connection, value.error());
                }
                refused += value ? 0 : 1;
                shown = value ? table_value(type, *value) : "error: " + value.error().message;
            }
            fmt::print("0x{:04X}  {:>3}  {:<40}  {}\n", index, sub_index, terminal_text(name),
                       shown);
        }
    }
    if (refused > 0) {
        fmt::print("{} objects refused\n", refused);
    }
    return kExitSuccess;
}

CLI::App* add_object_subcommand(CLI::App& od, const std::string& name,
                                const std::string& description, OdOptions& options) {
    CLI::App* command = od.add_subcommand(name, description);
    command->fallthrough(); // --port and the others may follow the subcommand's word
    command->add_option("index", options.index, "The object index, e.g. 0x1000")->required();
    command->add_option("sub", options.sub_index, "The sub-index, e.g. 0")->required();
    add_object_target_options(*command, options.target);
    command
        ->add_option("--type", options.type,
                     "How to read and write the value (default: the type the device's "
                     "dictionary gives the object, EPOS P or ESCON2; u32 for another node)")
        ->check(CLI::IsMember(value_type_names()));
    return command;
}

} // namespace

void add_od_command(CLI::App& app, int& exit_code) {
    auto options = std::make_shared<OdOptions>();
    CLI::App* od = app.add_subcommand(
        "od", "Read and write the objects of an EPOS P (RS-232/USB) or an ESCON2 (USB) over its "
              "service interface");
    add_service_client_options(*od, options->link);
    od->require_subcommand(1);

    add_object_subcommand(*od, "read", "Read one object", *options)
        ->callback([options, &exit_code] { exit_code = read_command(*options); });
    CLI::App* write = add_object_subcommand(*od, "write", "Write one object", *options);
    write->add_option("value", options->value, "The value: a number (0x for hex), text or bytes")
        ->required();
    write->callback([options, &exit_code] { exit_code = write_command(*options); });
    CLI::App* dump = od->add_subcommand(
        "dump", "Read every object of the device (EPOS P or ESCON2), as a table");
    dump->fallthrough();
    dump->callback([options, &exit_code] { exit_code = dump_command(*options); });
}

} // namespace eposp::device::cli
