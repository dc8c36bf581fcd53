#include "eposp/core/time.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

namespace eposp::core {
namespace {

struct Unit {
    std::string_view suffix;
    std::int64_t nanoseconds;
};

// Longest suffixes first so that "ms" is not read as "m" followed by garbage.
constexpr std::array kUnits{
    Unit{"ns", 1},
    Unit{"us", 1'000},
    Unit{"ms", 1'000'000},
    Unit{"s", 1'000'000'000},
    Unit{"m", 60'000'000'000},
    Unit{"h", 3'600'000'000'000},
};

} // namespace

std::optional<Duration> parse_duration(std::string_view text) {
    std::int64_t scale = 1'000'000'000;
    for (const Unit& unit : kUnits) {
        if (text.size() > unit.suffix.size() && text.ends_with(unit.suffix)) {
            text.remove_suffix(unit.suffix.size());
            scale = unit.nanoseconds;
            break;
        }
    }
    double value = 0;
    const auto [rest, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || rest != text.data() + text.size() || !(value >= 0) ||
        value * static_cast<double>(scale) > 9.2e18) {
        return std::nullopt;
    }
    return Duration{std::llround(value * static_cast<double>(scale))};
}

std::string format_duration(Duration d) {
    const std::int64_t ns = d.count();
    if (ns == 0) {
        return "0s";
    }
    auto unit = kUnits.rbegin();
    while (ns % unit->nanoseconds != 0) {
        ++unit; // ends at "ns", which divides everything
    }
    return fmt::format("{}{}", ns / unit->nanoseconds, unit->suffix);
}

std::string format_seconds_micros(TimePoint t) {
    const auto us = std::chrono::duration_cast<std::chrono::microseconds>(t.time_since_epoch());
    return fmt::format("{}.{:06}", us.count() / 1'000'000, us.count() % 1'000'000);
}

} // namespace eposp::core
