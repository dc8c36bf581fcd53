#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::core {

/// Every duration in eposp: integer nanoseconds, so periods and bit times add up without drift.
using Duration = std::chrono::nanoseconds;

/// The event loop's clock: time since the loop was created. It is never the wall clock; in
/// real-time pace the loop keeps it in step with the wall clock, in virtual pace it jumps.
struct LoopClock {
    using rep = Duration::rep;
    using period = Duration::period;
    using duration = Duration;
    using time_point = std::chrono::time_point<LoopClock, Duration>;
    static constexpr bool is_steady = true;
};
using TimePoint = LoopClock::time_point;

/// Parses a duration as users type it: `10s`, `250ms`, `1.5s`, `100us`, `2m`, `1h`, `500ns`.
/// A bare number is seconds. Returns nullopt on anything else, including negative values.
std::optional<Duration> parse_duration(std::string_view text);

/// Formats a duration in the largest unit that shows it as a whole number (`2s`, `1500ms`).
std::string format_duration(Duration d);

/// Seconds since the loop's start as `seconds.microseconds`, the form CAN traces use.
std::string format_seconds_micros(TimePoint t);

} // namespace eposp::core
