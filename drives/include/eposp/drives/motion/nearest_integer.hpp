#pragma once

#include <cmath>

namespace eposp::drives::motion {

/// std::lround (the nearest integer, halves away from zero) without the libm call: the drive
/// rounds its actual values every control period. Equal to std::lround for every input.
inline long nearest_integer(double value) {
    constexpr double kAllIntegersFrom = 4503599627370496.0; // 2^52: no fraction beyond
    if (!(std::abs(value) < kAllIntegersFrom)) {
        return std::lround(value); // whole already, or out of range, or NaN: as libm says
    }
    long whole = static_cast<long>(value);                      // towards zero
    const double fraction = value - static_cast<double>(whole); // exact below 2^52
    if (fraction >= 0.5) {
        ++whole;
    } else if (fraction <= -0.5) {
        --whole;
    }
    return whole;
}

} // namespace eposp::drives::motion
