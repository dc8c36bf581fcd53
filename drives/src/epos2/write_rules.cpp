#include "write_rules.hpp"

#include "eposp/canopen/entry_builder.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace eposp::drives::epos2 {
namespace {

// Table 8-103, single loop (the only structure of a 24/5): a gear is permitted with a DC motor (1)
// or a block commutated EC motor (11) on Incremental Encoder 1 (main sensor 1 or 2); without a
// sensor (0: Current Mode only, *A) and with a sinus commutated EC motor (10) on the encoder or a
// block commutated one on its hall sensors (*B) it is not, and the other combinations are not
// supported at all.
bool gear_permitted(const canopen::ObjectDictionary& od) {
    const auto motor_type = od.get_as<std::uint16_t>(0x6402, 0);
    const auto main_sensor = od.get_as<std::uint16_t>(0x2210, 2) & 0xF;
    return (motor_type == 1 || motor_type == 11) && (main_sensor == 1 || main_sensor == 2);
}

} // namespace

void guard_disable_state_objects(canopen::ObjectDictionary& od,
                                 std::function<bool()> power_stage_on) {
    // Every writable entry of these objects (the sections put the remark on the whole object).
    static constexpr std::array<std::uint16_t, 19> kWholeObjects = {
        0x2008, 0x207B, 0x2210, 0x2211, 0x2212, 0x2213, 0x2220, 0x2230, 0x2301, 0x2302,
        0x2303, 0x6089, 0x608A, 0x608B, 0x608C, 0x608D, 0x608E, 0x6402, 0x6410};
    for (const std::uint16_t index : kWholeObjects) {
        for (auto& [sub_index, entry] : od.find(index)->subs) {
            // 8.2.130: of the motor data only the pole pair number (sub 3) has the remark.
            if (!canopen::writable(entry.access) || (index == 0x6410 && sub_index != 3)) {
                continue;
            }
            canopen::Entry(entry).rule(
                [&entry, power_stage_on](std::span<const std::uint8_t> value) {
                    const bool changes = !std::ranges::equal(value, entry.value);
                    return changes && power_stage_on() ? canopen::AbortCode::DeviceState
                                                       : canopen::AbortCode::None;
                });
        }
    }
}

void guard_gear_configuration(canopen::ObjectDictionary& od) {
    canopen::Entry(*od.find(0x2230, 1)).rule([&od](std::span<const std::uint8_t> value) {
        return canopen::decode<std::uint32_t>(value) != 0 && !gear_permitted(od)
                   ? canopen::AbortCode::ParameterIncompatibility
                   : canopen::AbortCode::None;
    });
}

} // namespace eposp::drives::epos2
