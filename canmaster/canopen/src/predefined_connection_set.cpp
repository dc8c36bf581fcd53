#include "eposp/canopen/predefined_connection_set.hpp"

#include "eposp/canopen/cob_id.hpp"
#include "eposp/canopen/value_codec.hpp"

#include <array>

namespace eposp::canopen {
namespace {

constexpr std::uint16_t kCobIdEmcy = 0x1014;
constexpr std::uint16_t kSdoServerParameter = 0x1200;
constexpr std::size_t kPredefinedPdos = 4;

struct Entry {
    std::uint16_t index;
    std::uint8_t sub_index;
};

constexpr std::array<Entry, 11> kEntries = {{
    {kCobIdEmcy, 0},
    {kSdoServerParameter, 1},
    {kSdoServerParameter, 2},
    {0x1400, 1},
    {0x1401, 1},
    {0x1402, 1},
    {0x1403, 1},
    {0x1800, 1},
    {0x1801, 1},
    {0x1802, 1},
    {0x1803, 1},
}};

} // namespace

std::optional<std::uint32_t> predefined_pdo_cob_id(std::uint16_t communication_index, NodeId node) {
    const auto nth = [&](std::uint16_t first) {
        return 0x100U * static_cast<std::uint32_t>(communication_index - first) + node;
    };
    if (communication_index >= 0x1400 && communication_index < 0x1400 + kPredefinedPdos) {
        return 0x200U + nth(0x1400);
    }
    if (communication_index >= 0x1800 && communication_index < 0x1800 + kPredefinedPdos) {
        return 0x180U + nth(0x1800);
    }
    return std::nullopt;
}

std::optional<std::uint32_t> predefined_cob_id(std::uint16_t index, std::uint8_t sub_index,
                                               NodeId node) {
    if (index == kCobIdEmcy && sub_index == 0) {
        return kEmcyCanIdBase + node;
    }
    if (index == kSdoServerParameter && (sub_index == 1 || sub_index == 2)) {
        return (sub_index == 1 ? 0x600U : 0x580U) + node;
    }
    return sub_index == 1 ? predefined_pdo_cob_id(index, node) : std::nullopt;
}

void move_node_id_defaults(ObjectDictionary& od, NodeId from, NodeId to) {
    for (const auto [index, sub_index] : kEntries) {
        SubObject* sub = od.find(index, sub_index);
        if (sub == nullptr || sub->type != DataType::Unsigned32) {
            continue;
        }
        const auto old_default = decode<std::uint32_t>(sub->default_value);
        if ((old_default & kCobIdIdentifierBits) != *predefined_cob_id(index, sub_index, from)) {
            continue;
        }
        sub->default_value = encode((old_default & ~kCobIdIdentifierBits) |
                                    *predefined_cob_id(index, sub_index, to));
    }
}

} // namespace eposp::canopen
