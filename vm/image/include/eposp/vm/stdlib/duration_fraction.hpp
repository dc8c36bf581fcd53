#pragma once

// How the decimal fraction of a duration or time of day (`T#2.5ns`, `TOD#12:00:00.5`, and the
// same text read by STRING_TO_TIME) becomes nanoseconds: to nearest, ties to even on the whole
// value, as REAL_TO_TIME rounds (IEC 60559). One rule for the compiler's literals and the VM.

#include <cmath>
#include <cstdint>

namespace eposp::vm::stdlib {

/// The nanoseconds of a fraction worth `exact` (below one unit), rounded so that the whole
/// duration `before + result` is the nearest, ties to even: T#2.5ns is 2 ns, T#3.5ns is 4 ns.
inline std::int64_t fraction_nanoseconds(double exact, std::int64_t before) {
    const double below = std::floor(exact);
    auto result = static_cast<std::int64_t>(below);
    const double rest = exact - below;
    if (rest > 0.5 || (rest == 0.5 && ((before ^ result) & 1) != 0)) {
        ++result;
    }
    return result;
}

} // namespace eposp::vm::stdlib
