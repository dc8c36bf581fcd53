#include "eposp/drives/plant/shaft_sensors.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace eposp::drives::plant {

namespace {

std::int64_t floor_div(std::int64_t value, std::int64_t divisor) {
    const std::int64_t quotient = value / divisor;
    return (value % divisor != 0 && value < 0) ? quotient - 1 : quotient;
}

} // namespace

std::int64_t counts_per_turn(int encoder_pulses) {
    return 4 * std::int64_t{encoder_pulses};
}

// Both run at every 0.1 ms step of every axis: floor without the libm call, and no division
// while the shaft stands.
std::int64_t quadcounts(double motor_angle, int encoder_pulses) {
    const double turns = motor_angle / (2 * std::numbers::pi);
    const double counts = turns * static_cast<double>(counts_per_turn(encoder_pulses));
    const auto truncated = static_cast<std::int64_t>(counts);
    return static_cast<double>(truncated) > counts ? truncated - 1 : truncated;
}

bool index_passed(std::int64_t before, std::int64_t after, int encoder_pulses) {
    if (before == after) {
        return false;
    }
    const std::int64_t turn = counts_per_turn(encoder_pulses);
    // The index sits at the boundary count; crossing it either way changes the revolution.
    return floor_div(before, turn) != floor_div(after, turn);
}

std::uint8_t hall_pattern(double motor_angle, int pole_pairs) {
    static constexpr std::array<std::uint8_t, 6> kSequence = {1, 3, 2, 6, 4, 5};
    const double electrical_turns = motor_angle * pole_pairs / (2 * std::numbers::pi);
    const double fraction = electrical_turns - std::floor(electrical_turns);
    const auto sector = static_cast<std::size_t>(fraction * 6) % kSequence.size();
    return kSequence[sector];
}

std::uint8_t hall_inputs(std::uint8_t pattern, const SensorFaults& faults) {
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
