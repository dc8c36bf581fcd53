#include "network_escon2.hpp"

#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/entry_builder.hpp"
#include "eposp/drives/escon2/escon2_dictionary.hpp"
#include "text_words.hpp"
#include "yaml_values.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace eposp::device {
namespace {

using drives::escon2::Escon2Hardware;

// The products of ESCON2 FW spec 6.2 ("Hardware" column), as maxon names them.
const std::map<std::string, Escon2Hardware> kHardware = {
    {"module 60/30", Escon2Hardware::Module60_30},
    {"compact 60/30", Escon2Hardware::Compact60_30},
    {"micro 60/5", Escon2Hardware::Micro60_5},
    {"nano 24/2", Escon2Hardware::Nano24_2}};

bool is_name(const std::string& name) {
    return !name.empty() && std::ranges::all_of(name, [](unsigned char c) {
        return std::isalnum(c) != 0 || c == '_' || c == '-';
    });
}

bool fits(canopen::DataType type, std::int64_t value) {
    const unsigned bits = 8 * static_cast<unsigned>(canopen::fixed_size(type).value_or(8));
    if (bits >= 64) {
        return canopen::is_signed_integer(type) || value >= 0;
    }
    if (canopen::is_signed_integer(type)) {
        const std::int64_t half = std::int64_t{1} << (bits - 1);
        return value >= -half && value < half;
    }
    return value >= 0 && value < (std::int64_t{1} << bits);
}

Escon2Machine::Parameter read_parameter(yaml::Reader& in, const YAML::Node& node,
                                        canopen::ObjectDictionary& od) {
    Escon2Machine::Parameter parameter;
    std::optional<std::int64_t> value;
    in.each_key(node, "parameters",
                {{"index",
                  [&](const YAML::Node& v) {
                      parameter.index = in_range<std::uint16_t>(in, v, "index", 0x1000, 0xFFFF);
                  }},
                 {"sub",
                  [&](const YAML::Node& v) {
                      parameter.sub_index = in_range<std::uint8_t>(in, v, "sub", 0, 0xFF);
                  }},
                 {"value", [&](const YAML::Node& v) {
                      value = in.scalar<std::int64_t>(v, "value");
                  }}});
    if (parameter.index == 0 || !value) {
        in.fail(node, "a parameter needs its 'index' and 'value' ('sub' is 0 without one)");
    }
    const canopen::SubObject* entry = od.find(parameter.index, parameter.sub_index);
    const auto where = fmt::format("0x{:04X} sub {}", parameter.index, parameter.sub_index);
    if (entry == nullptr) {
        in.fail(node, where + ": the ESCON2 has no such object");
    }
    if (!canopen::is_signed_integer(entry->type) && !canopen::is_unsigned_integer(entry->type)) {
        in.fail(node, where + ": only integer objects can be set here");
    }
    if (!fits(entry->type, *value)) {
        in.fail(node, fmt::format("{}: {} does not fit its type {}", where, *value,
                                  canopen::to_string(entry->type)));
    }
    parameter.value = canopen::encode_integer(entry->type, *value);
    // Written in order, so that a rule between objects (one functionality per pin, the supply
    // limits apart) sees the earlier parameters as the device will.
    if (const canopen::AbortCode refused =
            od.write(parameter.index, parameter.sub_index, parameter.value);
        refused != canopen::AbortCode::None) {
        in.fail(node, fmt::format("{}: the ESCON2 refuses {}: {}", where, *value,
                                  canopen::describe(refused)));
    }
    return parameter;
}

} // namespace

Escon2Machine
read_escon2_machine(yaml::Reader& in, const YAML::Node& node, std::string_view section,
                    const std::filesystem::path& base,
                    std::map<std::string, std::function<void(const YAML::Node&)>> more) {
    Escon2Machine machine;
    std::optional<YAML::Node> parameters;
    more.emplace("hardware", [&](const YAML::Node& value) {
        const auto found = kHardware.find(lower(in.scalar<std::string>(value, "hardware")));
        if (found == kHardware.end()) {
            in.fail(value, "hardware must be 'Module 60/30', 'Compact 60/30', "
                           "'Micro 60/5' or 'Nano 24/2'");
        }
        machine.hardware = found->second;
    });
    more.emplace("plant",
                 [&](const YAML::Node& value) { machine.plant = read_plant(in, value, base); });
    more.emplace("parameters", [&](const YAML::Node& value) {
        if (!value.IsSequence()) {
            in.fail(value, "'parameters' must be a list");
        }
        parameters = value;
    });
    in.each_key(node, section, more);
    if (parameters) {
        // After the hardware, whatever the keys' order: it decides defaults and ranges.
        drives::escon2::Escon2DictionaryConfig config;
        config.hardware = machine.hardware;
        drives::escon2::Escon2Dictionary device(std::move(config));
        (void)device.power_up();
        for (const YAML::Node& entry : *parameters) {
            machine.parameters.push_back(read_parameter(in, entry, device.objects()));
        }
    }
    return machine;
}

NetworkEscon2 read_escon2(yaml::Reader& in, const YAML::Node& node,
                          const std::filesystem::path& base) {
    std::string name;
    Escon2Machine machine =
        read_escon2_machine(in, node, "escon2", base,
                            {{"name", [&](const YAML::Node& value) {
                                  name = in.scalar<std::string>(value, "name");
                                  if (!is_name(name)) {
                                      in.fail(value, "name must be letters, digits, '_' or '-'");
                                  }
                              }}});
    if (name.empty()) {
        in.fail(node, "an ESCON2 needs its 'name'");
    }
    NetworkEscon2 escon2;
    static_cast<Escon2Machine&>(escon2) = std::move(machine);
    escon2.name = std::move(name);
    return escon2;
}

} // namespace eposp::device
