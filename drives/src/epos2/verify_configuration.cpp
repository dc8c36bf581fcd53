#include "verify_configuration.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

namespace eposp::drives::epos2 {
namespace {

constexpr std::uint16_t kVerifyConfigurationIndex = 0x1020;

// Table 8-67, note: "Subindexes in brackets are persistent but will not be checked".
constexpr std::array<std::uint16_t, 20> kUnchecked = {
    0x1005, 0x1012, 0x1014, 0x1020, 0x2000, 0x2001, 0x2002, 0x2005, 0x2006, 0x2081,
    0x6081, 0x6083, 0x6084, 0x6085, 0x6089, 0x608A, 0x608B, 0x608C, 0x608D, 0x608E,
};

bool checked(const canopen::Object& object) {
    if (std::ranges::find(kUnchecked, object.index) != kUnchecked.end()) {
        return false;
    }
    return std::ranges::any_of(object.subs,
                               [](const auto& entry) { return entry.second.persistent; });
}

} // namespace

void watch_verified_configuration(canopen::ObjectDictionary& od) {
    for (const auto& [index, object] : od.objects()) {
        if (!checked(object)) {
            continue;
        }
        od.on_change(index, [&od](std::uint16_t changed, std::uint8_t sub_index) {
            if (od.find(changed, sub_index)->persistent) {
                od.set_as(kVerifyConfigurationIndex, 1, std::uint32_t{0});
                od.set_as(kVerifyConfigurationIndex, 2, std::uint32_t{0});
            }
        });
    }
}

} // namespace eposp::drives::epos2
