#include "eposp/drives/plant/shaft_sensors.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace eposp::drives::plant {

namespace {

// The hall patterns of the six sectors of an electrical revolution, for positive rotation.
constexpr std::array<std::uint8_t, 6> kHallSequence = {1, 3, 2, 6, 4, 5};

std::int64_t floor_div(std::int64_t value, std::int64_t divisor) {
    const std::int64_t quotient = value / divisor;
    return (value % divisor != 0 && value < 0) ? quotient - 1 : quotient;
}

} // namespace

Revolution revolution_of(std::int64_t count, int encoder_pulses) {
    const std::int64_t turn = counts_per_turn(encoder_pulses);
    const std::int64_t first = floor_div(count, turn) * turn;
    return {.first = first, .end = first + turn};
}

bool index_passed(std::int64_t before, std::int64_t after, int encoder_pulses) {
    // The index sits at the boundary count; crossing it either way changes the revolution.
    return before != after && !revolution_of(before, encoder_pulses).holds(after);
}

std::uint8_t hall_pattern(double motor_angle, int pole_pairs) {
    const double electrical_turns = motor_angle * pole_pairs / (2 * std::numbers::pi);
    const double fraction = electrical_turns - std::floor(electrical_turns);
    const auto sector = static_cast<std::size_t>(fraction * 6) % kHallSequence.size();
    return kHallSequence[sector];
}

std::optional<int> hall_sector(std::uint8_t pattern) {
    const auto* found = std::ranges::find(kHallSequence, pattern);
    if (found == kHallSequence.end()) {
        return std::nullopt;
    }
    return static_cast<int>(found - kHallSequence.begin());
}

std::uint8_t hall_inputs(std::uint8_t pattern, const SensorFaults& faults) {
    if (faults.supply_overloaded) {
        return 0;
    }
    return static_cast<std::uint8_t>((pattern & ~faults.hall_stuck_mask) |
                                     (faults.hall_stuck_levels & faults.hall_stuck_mask));
}

SwitchStates switch_states(const SwitchLayout& layout, std::int64_t position) {
    SwitchStates states;
    states.negative_limit = layout.negative_limit && position <= *layout.negative_limit;
    states.positive_limit = layout.positive_limit && position >= *layout.positive_limit;
    if (layout.home) {
        const std::int64_t beyond_edge =
            layout.home_active_above ? position - *layout.home : *layout.home - 1 - position;
        states.home =
            beyond_edge >= 0 && (!layout.home_length || beyond_edge < *layout.home_length);
    }
    return states;
}

} // namespace eposp::drives::plant
