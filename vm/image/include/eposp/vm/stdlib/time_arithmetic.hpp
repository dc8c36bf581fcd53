#pragma once

// IEC 61131-3 (3rd ed.) table 30: the time and date arithmetic that is more than one add, on the
// VM's nanosecond counts (TIME, LTIME, DATE, TOD and DT; DATE and DT since 1970-01-01, TOD since
// midnight). The VM's natives (ADD_TOD_TIME, MUL_TIME, DT_TO_DATE...) are these; the compiler
// folds constants with the same ones.

#include "eposp/vm/stdlib/time_units.hpp"
#include "eposp/vm/value_semantics.hpp"

#include <cstdint>
#include <optional>

namespace eposp::vm::stdlib {

/// A time of day from a count that may be beyond one day: TOD arithmetic wraps around midnight,
/// as CODESYS does (DT_TO_TOD too).
inline std::int64_t wrap_to_day(std::int64_t ns) {
    const auto r = ns % kNsPerDay;
    return r < 0 ? r + kNsPerDay : r;
}

/// The midnight that begins the day of `ns`: DT_TO_DATE.
inline std::int64_t floor_to_day(std::int64_t ns) {
    return ns - wrap_to_day(ns);
}

/// ADD_TOD_TIME and SUB_TOD_TIME: both operands are reduced to one day first, so that no sum
/// overflows whatever they hold.
inline std::int64_t add_tod_time(std::int64_t tod, std::int64_t time) {
    return wrap_to_day(wrap_to_day(tod) + wrap_to_day(time));
}
inline std::int64_t sub_tod_time(std::int64_t tod, std::int64_t time) {
    return wrap_to_day(wrap_to_day(tod) - wrap_to_day(time));
}

/// LREAL to a nanosecond count exactly as CvtF64I64 (REAL_TO_TIME) does: to nearest, ties to
/// even (IEC 60559), saturating, NaN gives 0.
inline std::int64_t round_to_ns(double ns) {
    return detail::convert<std::int64_t>(ns);
}

// MUL_TIME / DIV_TIME (IN1: TIME, IN2: ANY_NUM): integer factors (as LINT) wrap like LINT
// arithmetic, real ones (as LREAL) round to the nanosecond. A division by zero is none: the
// native stops the task.
inline std::int64_t mul_time(std::int64_t time, std::int64_t factor) {
    return detail::mul(time, factor); // Mul64
}
inline std::int64_t mul_time(std::int64_t time, double factor) {
    return round_to_ns(static_cast<double>(time) * factor);
}
inline std::optional<std::int64_t> div_time(std::int64_t time, std::int64_t divisor) {
    if (divisor == 0) {
        return std::nullopt;
    }
    return detail::divide(time, divisor); // DivI64: MIN / -1 wraps
}
inline std::optional<std::int64_t> div_time(std::int64_t time, double divisor) {
    if (divisor == 0.0) {
        return std::nullopt;
    }
    return round_to_ns(static_cast<double>(time) / divisor);
}

} // namespace eposp::vm::stdlib
