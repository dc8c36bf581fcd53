#pragma once

#include <cstdint>

namespace eposp::drives::epos2 {

/// Position Compare 0x207A (EPOS2 FW spec 8.2.61, table 8-96).
struct PositionCompareConfiguration {
    std::uint16_t configuration = 0;  ///< sub 1: enable, operational, interval, direction bits
    std::int32_t reference = 0;       ///< sub 2
    std::int32_t interval_width = 0;  ///< sub 3
    std::uint16_t repetitions = 0;    ///< sub 4, 0 = infinite
    std::uint16_t pulse_width_us = 0; ///< sub 5
    /// 0x2210 sub 2: compare needs an incremental encoder (1 with, 2 without index).
    std::uint16_t sensor_type = 1;
};

/// Sets the position compare output for a pulse each time the actual position passes a compare
/// position in a direction the configuration compares: the reference alone (single position
/// mode), or the reference and its intervals of table 8-96's interval mode (position sequence
/// mode). The pulse lasts the pulse width rounded to 100 µs, at least 500 µs (a standard output);
/// the output is sampled every control period, so it shows in at least one.
class PositionCompare {
public:
    void configure(const PositionCompareConfiguration& config) { config_ = config; }

    /// One control period at `now` (seconds): the actual position moved from `before` to
    /// `actual`. Returns the compare output's state.
    bool update(double now, std::int64_t before, std::int64_t actual);
    bool enabled() const;

private:
    /// Whether a compare position lies in [low, high].
    bool hits(std::int64_t low, std::int64_t high) const;

    PositionCompareConfiguration config_;
    double pulse_end_ = -1;
};

} // namespace eposp::drives::epos2
