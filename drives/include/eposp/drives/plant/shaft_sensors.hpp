#pragma once

#include <cstdint>
#include <numbers>
#include <optional>

namespace eposp::drives::plant {

/// EPOS2 FW spec 3.3.1: positions are quadcounts, 4 × encoder pulses per revolution (0x2210).
inline std::int64_t counts_per_turn(int encoder_pulses) {
    return 4 * std::int64_t{encoder_pulses};
}

/// The quadcount reading of an incremental encoder on the motor shaft: the angle quantised
/// downwards to whole counts, zero at angle zero. Inline, as every 0.1 ms step of every axis
/// reads it: floor without the libm call.
inline std::int64_t quadcounts(double motor_angle, int encoder_pulses) {
    const double turns = motor_angle / (2 * std::numbers::pi);
    const double counts = turns * static_cast<double>(counts_per_turn(encoder_pulses));
    const auto truncated = static_cast<std::int64_t>(counts);
    return static_cast<double>(truncated) > counts ? truncated - 1 : truncated;
}

/// The encoder revolution that holds a count: from a multiple of counts_per_turn up to the next.
/// The index channel pulses where a reading leaves it.
struct Revolution {
    std::int64_t first = 0;
    std::int64_t end = 0; ///< one past its last count
    bool holds(std::int64_t count) const { return count >= first && count < end; }
};
Revolution revolution_of(std::int64_t count, int encoder_pulses);

/// Whether the index channel pulsed between two readings: once per revolution, where the count
/// is a multiple of counts_per_turn.
bool index_passed(std::int64_t before, std::int64_t after, int encoder_pulses);

/// The three hall sensor bits of an EC motor (8.2.46: bit 0 = sensor 1 …): six 60° sectors per
/// electrical revolution, pole_pairs electrical revolutions per turn, in the usual 120° sequence
/// 1, 3, 2, 6, 4, 5 for positive rotation.
std::uint8_t hall_pattern(double motor_angle, int pole_pairs);

/// The 60° sector (0 - 5) of the electrical revolution that a hall pattern shows, as
/// hall_pattern numbers them; none for the impossible combinations 000 and 111.
std::optional<int> hall_sector(std::uint8_t pattern);

/// Faults of the motor's sensors that a test injects (EPOS2 FW spec 4.2.23 - 4.2.31 list them as
/// causes): what the drive's sensor inputs read instead of the shaft's angle.
struct SensorFaults {
    bool encoder_broken = false; ///< a broken encoder line: the channels carry no signal
    bool index_missing = false;  ///< the encoder's index channel never pulses
    /// The lines per turn of the encoder actually mounted, when not those configured (0x2210).
    std::optional<int> encoder_pulses;
    /// Hall sensor inputs held at a level whatever the angle (a broken sensor or supply): bit n
    /// of `hall_stuck_mask` holds sensor n + 1 at bit n of `hall_stuck_levels`.
    std::uint8_t hall_stuck_mask = 0;
    std::uint8_t hall_stuck_levels = 0;
    /// The 5 V supply of the encoder and Hall sensor connectors overloaded (a short in a sensor
    /// cable): neither sensor is powered, the encoder's channels and the Hall inputs read low.
    bool supply_overloaded = false;

    /// The encoder's channels carry no signal: a broken line or no supply.
    bool encoder_silent() const { return encoder_broken || supply_overloaded; }

    friend bool operator==(const SensorFaults&, const SensorFaults&) = default;
};

/// The hall sensor inputs as the drive reads them: `pattern` with the stuck sensors at their level.
std::uint8_t hall_inputs(std::uint8_t pattern, const SensorFaults& faults);

/// Simulated switches at configurable positions in quadcounts; an absent switch never trips.
struct SwitchLayout {
    std::optional<std::int64_t> negative_limit; ///< active at and below this position
    std::optional<std::int64_t> positive_limit; ///< active at and above this position
    std::optional<std::int64_t> home;           ///< the home switch's edge
    bool home_active_above = true;              ///< which side of the edge the switch is pressed
    /// A cam active over only a portion of the travel (EPOS2 FW spec 5.4.3.3): so many counts
    /// from the edge on its active side; without it the switch stays pressed to the end.
    std::optional<std::int64_t> home_length;
};

struct SwitchStates {
    bool negative_limit = false;
    bool positive_limit = false;
    bool home = false;

    friend bool operator==(const SwitchStates&, const SwitchStates&) = default;
};

SwitchStates switch_states(const SwitchLayout& layout, std::int64_t position);

} // namespace eposp::drives::plant
