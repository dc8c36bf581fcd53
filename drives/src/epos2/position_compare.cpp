#include "eposp/drives/epos2/position_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eposp::drives::epos2 {
namespace {

// Table 8-96.
constexpr std::uint16_t kEnableBit = 1U << 0;
unsigned operational_mode(std::uint16_t c) {
    return (c >> 1) & 3U;
}
unsigned interval_mode(std::uint16_t c) {
    return (c >> 3) & 3U;
}
unsigned direction_dependency(std::uint16_t c) {
    return (c >> 5) & 3U;
}

constexpr unsigned kSequenceMode = 1;
constexpr unsigned kNegativeIntervals = 0;
constexpr unsigned kPositiveIntervals = 1;
constexpr unsigned kBothIntervals = 2;
constexpr unsigned kPositiveDirection = 1; // 0: negative
constexpr unsigned kBothDirections = 2;

// Control periods are whole microseconds; their times in seconds are doubles.
constexpr double kTimeTolerance = 1e-9;

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0);
}

// 8.2.61 sub 5: rounded to 100 µs, standard outputs at least 500 µs.
double pulse_seconds(std::uint16_t width_us) {
    const double rounded = std::round(width_us / 100.0) * 100.0;
    return std::max(rounded, 500.0) * 1e-6;
}

} // namespace

bool PositionCompare::enabled() const {
    const std::uint16_t c = config_.configuration;
    // The reserved values of table 8-96 compare nothing; 8.2.61: incremental encoders only.
    return (c & kEnableBit) != 0 && operational_mode(c) <= kSequenceMode &&
           interval_mode(c) <= kBothIntervals && direction_dependency(c) <= kBothDirections &&
           (config_.sensor_type == 1 || config_.sensor_type == 2);
}

bool PositionCompare::hits(std::int64_t low, std::int64_t high) const {
    const std::int64_t reference = config_.reference;
    const std::int64_t width = config_.interval_width;
    if (operational_mode(config_.configuration) != kSequenceMode || width == 0) {
        return low <= reference && reference <= high;
    }
    // The compare positions are reference + k × width, k in the interval mode's range.
    constexpr std::int64_t kEndless = std::numeric_limits<std::int64_t>::max();
    const std::int64_t n = config_.repetitions == 0 ? kEndless : config_.repetitions;
    const unsigned intervals = interval_mode(config_.configuration);
    const std::int64_t k_min = intervals == kPositiveIntervals ? 0 : -n;
    const std::int64_t k_max = intervals == kNegativeIntervals ? 0 : n;
    const std::int64_t first = -floor_div(reference - low, width); // ceil((low - ref) / width)
    const std::int64_t last = floor_div(high - reference, width);
    return std::max(first, k_min) <= std::min(last, k_max);
}

bool PositionCompare::update(double now, std::int64_t before, std::int64_t actual) {
    if (enabled() && actual != before) {
        const bool positive = actual > before;
        const unsigned direction = direction_dependency(config_.configuration);
        const bool compared =
            direction == kBothDirections || (direction == kPositiveDirection) == positive;
        // The positions passed in this period: (before, actual] moving up, [actual, before)
        // moving down, so that a position reached and left again triggers once each way.
        const bool passed = positive ? hits(before + 1, actual) : hits(actual, before - 1);
        if (compared && passed) {
            pulse_end_ = now + pulse_seconds(config_.pulse_width_us);
        }
    }
    return now < pulse_end_ - kTimeTolerance;
}

} // namespace eposp::drives::epos2
