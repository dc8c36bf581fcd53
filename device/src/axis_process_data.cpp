#include "eposp/device/axis_process_data.hpp"

#include "eposp/canopen/pdo_mapping.hpp"
#include "eposp/canopen/pdo_objects.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/vm/process_image.hpp"

#include <fmt/format.h>
#include <stdexcept>

namespace eposp::device {
namespace {

using canopen::MappingEntry;
using canopen::PdoCobId;
using canopen::PdoDirection;

constexpr std::uint16_t kControlword = 0x6040;
constexpr std::uint16_t kStatusword = 0x6041;
constexpr std::uint16_t kModesOfOperation = 0x6060;
constexpr std::uint16_t kPositionActualValue = 0x6064;
constexpr std::uint16_t kTargetPosition = 0x607A;
constexpr std::int8_t kProfilePositionMode = 1;
constexpr std::uint8_t kAxisStatuswordSub = 2;

constexpr std::uint32_t kTpdo1Base = 0x180;
constexpr std::uint32_t kRpdo1Base = 0x200;

/// Writes that set one PDO up: invalid, the mapping, the transmission type, valid again.
void add_pdo(std::vector<manager::ConfigurationWrite>& writes, PdoDirection direction,
             std::size_t number, std::uint32_t cob_id, std::uint8_t transmission_type,
             const std::vector<MappingEntry>& mapping) {
    const std::uint16_t communication = canopen::pdo_communication_index(direction, number);
    const std::uint16_t mapping_index = canopen::pdo_mapping_index(direction, number);
    const auto add = [&writes](std::uint16_t index, std::uint8_t sub, canopen::Bytes value) {
        writes.push_back({index, sub, std::move(value)});
    };
    add(communication, canopen::kPdoCobIdSub, canopen::encode(cob_id | PdoCobId::kInvalid));
    add(mapping_index, 0, canopen::encode(std::uint8_t{0}));
    for (std::size_t entry = 0; entry < mapping.size(); ++entry) {
        add(mapping_index, static_cast<std::uint8_t>(entry + 1),
            canopen::encode(mapping[entry].raw()));
    }
    add(mapping_index, 0, canopen::encode(static_cast<std::uint8_t>(mapping.size())));
    add(communication, canopen::kPdoTransmissionTypeSub, canopen::encode(transmission_type));
    add(communication, canopen::kPdoCobIdSub, canopen::encode(cob_id));
}

/// The same writes into a dictionary, checked as a remote write is: a refusal is a mistake of
/// this file, not of the user.
void write_all(canopen::ObjectDictionary& od,
               const std::vector<manager::ConfigurationWrite>& writes) {
    for (const manager::ConfigurationWrite& write : writes) {
        if (const canopen::AbortCode code = od.write(write.index, write.sub_index, write.value);
            code != canopen::AbortCode::None) {
            throw std::logic_error(fmt::format("axis PDO set-up: 0x{:04X} sub {} refused: {}",
                                               write.index, write.sub_index,
                                               canopen::describe(code)));
        }
    }
}

std::uint16_t axis_index(std::uint8_t axis) {
    return static_cast<std::uint16_t>(kAxisIndex + axis);
}

} // namespace

AxisChannels AxisChannels::of(std::uint8_t axis) {
    if (axis < vm::kEntriesPerObject) {
        const auto sub = static_cast<std::uint8_t>(axis + 1);
        return {{0xA100, sub}, {0xA1C0, sub}, {0xA580, sub}, {0xA640, sub}};
    }
    const auto sub = static_cast<std::uint8_t>(axis - vm::kEntriesPerObject + 1);
    return {{0xA0C0, sub}, {0xA200, sub}, {0xA540, sub}, {0xA680, sub}};
}

std::vector<manager::ConfigurationWrite> axis_slave_configuration(canopen::NodeId node) {
    std::vector<manager::ConfigurationWrite> writes;
    add_pdo(writes, PdoDirection::Transmit, 1, PdoCobId::kNoRtr | (kTpdo1Base + node), 1,
            {{kStatusword, 0, 16}, {kStatusword, 0, 16}, {kPositionActualValue, 0, 32}});
    add_pdo(writes, PdoDirection::Receive, 1, kRpdo1Base + node, canopen::kEventDrivenProfile,
            {{kControlword, 0, 16}, {kTargetPosition, 0, 32}});
    writes.push_back({kModesOfOperation, 0, canopen::encode(kProfilePositionMode)});
    return writes;
}

void configure_axis_pdos(canopen::ObjectDictionary& od, std::size_t pdo_number,
                         canopen::NodeId node, std::uint8_t axis) {
    std::vector<manager::ConfigurationWrite> writes;
    const AxisChannels channels = AxisChannels::of(axis);
    add_pdo(writes, PdoDirection::Receive, pdo_number, kTpdo1Base + node,
            canopen::kEventDrivenProfile,
            {{axis_index(axis), kAxisStatuswordSub, 16},
             {channels.statusword.index, channels.statusword.sub_index, 16},
             {channels.actual_position.index, channels.actual_position.sub_index, 32}});
    add_pdo(writes, PdoDirection::Transmit, pdo_number, kRpdo1Base + node, 1,
            {{channels.controlword.index, channels.controlword.sub_index, 16},
             {channels.target_position.index, channels.target_position.sub_index, 32}});
    write_all(od, writes);
}

} // namespace eposp::device
