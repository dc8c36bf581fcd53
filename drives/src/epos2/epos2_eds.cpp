#include "eposp/drives/epos2/epos2_eds.hpp"

#include "eposp/canopen/eds_export.hpp"
#include "eposp/canopen/predefined_connection_set.hpp"
#include "eposp/drives/epos2/epos2_dictionary.hpp"

#include <fmt/format.h>
#include <utility>

namespace eposp::drives::epos2 {
namespace {

constexpr canopen::NodeId kExportNodeId = 1;

std::string section_name(std::uint16_t index, std::uint8_t sub_index, bool is_variable) {
    return is_variable ? fmt::format("[{:04X}]\n", index)
                       : fmt::format("[{:04X}sub{:X}]\n", index, sub_index);
}

// Chapter 8 gives the COB-IDs of the predefined connection set as "0x40000180 + Node ID" (8.2.26,
// …): CiA 306 writes such a default as $NODEID+0x40000180, as maxon's EDS does, so that a tool
// gives each node its own.
std::string with_node_id_expressions(std::string eds, const canopen::ObjectDictionary& od) {
    for (const auto& [index, object] : od.objects()) {
        for (const auto& [sub_index, sub] : object.subs) {
            const auto cob_id = canopen::predefined_cob_id(index, sub_index, kExportNodeId);
            if (!cob_id) {
                continue;
            }
            const auto value = canopen::decode<std::uint32_t>(sub.default_value);
            if ((value & 0x1FFFFFFF) != *cob_id) {
                continue; // a default the EPOS2 does not derive from the node-ID
            }
            const std::string section =
                section_name(index, sub_index, object.code == canopen::ObjectCode::Var);
            const std::size_t start = eds.find(section);
            const std::string key = "\nDefaultValue=";
            const std::size_t line = eds.find(key, start);
            const std::size_t end = eds.find('\n', line + key.size());
            if (start == std::string::npos || line == std::string::npos ||
                eds.find("\n[", start) < line) {
                throw std::logic_error("the EDS export has no DefaultValue for " + section);
            }
            eds.replace(line + key.size(), end - line - key.size(),
                        fmt::format("$NODEID+0x{:08X}", value - kExportNodeId));
        }
    }
    return eds;
}

} // namespace

std::string epos2_eds() {
    // The store is never written: an export only reads the defaults.
    Epos2DictionaryConfig config;
    config.node_id = kExportNodeId;
    config.parameter_file = "epos2-parameters.bin";
    const Epos2Dictionary dictionary(std::move(config));
    return with_node_id_expressions(canopen::export_eds(dictionary.objects(), epos2_device_info()),
                                    dictionary.objects());
}

} // namespace eposp::drives::epos2
