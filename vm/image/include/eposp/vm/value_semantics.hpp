#pragma once

// The IEC 61131-3 meaning of each operation on machine values, one template per family; the
// interpreter instantiates them per type. Integer arithmetic is done on unsigned types of at
// least int's width, so that wrap-around is defined behaviour and no promotion to signed int
// can overflow.

#include "eposp/vm/scalar.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace eposp::vm::detail {

template <typename T>
using Unsigned =
    std::conditional_t<(sizeof(T) < sizeof(unsigned)), unsigned, std::make_unsigned_t<T>>;

template <typename T>
T add(T x, T y) {
    if constexpr (std::is_floating_point_v<T>) {
        return x + y;
    } else {
        return static_cast<T>(Unsigned<T>(x) + Unsigned<T>(y));
    }
}
template <typename T>
T sub(T x, T y) {
    if constexpr (std::is_floating_point_v<T>) {
        return x - y;
    } else {
        return static_cast<T>(Unsigned<T>(x) - Unsigned<T>(y));
    }
}
template <typename T>
T mul(T x, T y) {
    if constexpr (std::is_floating_point_v<T>) {
        return x * y;
    } else {
        return static_cast<T>(Unsigned<T>(x) * Unsigned<T>(y));
    }
}
template <typename T>
T neg(T x) {
    if constexpr (std::is_floating_point_v<T>) {
        return -x;
    } else {
        return static_cast<T>(Unsigned<T>(0) - Unsigned<T>(x));
    }
}
template <typename T>
T abs(T x) {
    if constexpr (std::is_floating_point_v<T>) {
        return std::fabs(x);
    } else if constexpr (std::is_signed_v<T>) {
        return x < 0 ? neg(x) : x; // ABS(MIN) wraps to MIN, as NEG does
    } else {
        return x;
    }
}

/// Integer division with a non-zero divisor; MIN / -1 wraps to MIN instead of trapping.
template <typename T>
T divide(T x, T y) {
    if constexpr (std::is_floating_point_v<T>) {
        return x / y;
    } else {
        if constexpr (std::is_signed_v<T>) {
            if (y == -1) {
                return neg(x);
            }
        }
        return static_cast<T>(x / y);
    }
}
/// IEC MOD: the sign follows the dividend (x - (x / y) * y); non-zero divisor.
template <typename T>
T modulo(T x, T y) {
    if constexpr (std::is_signed_v<T>) {
        if (y == -1) {
            return 0;
        }
    }
    return static_cast<T>(x % y);
}

template <typename T>
constexpr unsigned kBits = sizeof(T) * 8;

template <typename T>
T shift_left(T x, std::uint32_t n) {
    return n >= kBits<T> ? T{0} : static_cast<T>(Unsigned<T>(x) << n);
}
template <typename T>
T shift_right(T x, std::uint32_t n) {
    return n >= kBits<T> ? T{0} : static_cast<T>(Unsigned<T>(x) >> n);
}
template <typename T>
T rotate_left(T x, std::uint32_t n) {
    n %= kBits<T>;
    return n == 0 ? x : static_cast<T>((Unsigned<T>(x) << n) | (Unsigned<T>(x) >> (kBits<T> - n)));
}
template <typename T>
T rotate_right(T x, std::uint32_t n) {
    n %= kBits<T>;
    return n == 0 ? x : static_cast<T>((Unsigned<T>(x) >> n) | (Unsigned<T>(x) << (kBits<T> - n)));
}

/// A real already rounded to an integral value, clamped into To's range (NaN gives 0): the
/// C++ cast alone is undefined outside that range.
template <typename To, typename From>
To saturate(From integral) {
    if (std::isnan(integral)) {
        return 0;
    }
    constexpr auto lo = static_cast<From>(std::numeric_limits<To>::min());
    // For 64-bit targets the maximum is not representable and rounds up to 2^63 or 2^64,
    // which is then correctly the first value out of range.
    constexpr auto hi = static_cast<From>(std::numeric_limits<To>::max());
    if (integral <= lo) {
        return std::numeric_limits<To>::min();
    }
    if (integral >= hi) {
        return std::numeric_limits<To>::max();
    }
    return static_cast<To>(integral);
}

/// IEC 61131-3 type conversion (*_TO_*): integers wrap modulo 2^n, anything to BOOL is <> 0,
/// BOOL is 0 or 1, a real to an integer rounds to nearest with ties to even, as IEC 60559 does
/// (IEC 61131-3 3rd ed. 6.6.2.5.6: REAL_TO_INT(2.5) = 2, (3.5) = 4, (-2.5) = -2) and saturates.
/// nearbyint rounds so in the default rounding mode, which nothing here changes.
template <typename To, typename From>
To convert(From x) {
    if constexpr (std::is_same_v<From, BoolByte>) {
        return convert<To>(static_cast<std::uint8_t>(static_cast<std::uint8_t>(x) != 0));
    } else if constexpr (std::is_same_v<To, BoolByte>) {
        return static_cast<BoolByte>(x != From{0} ? 1 : 0);
    } else if constexpr (std::is_floating_point_v<From> && std::is_integral_v<To>) {
        return saturate<To>(std::nearbyint(x));
    } else {
        return static_cast<To>(x);
    }
}

/// TRUNC: toward zero, saturating.
template <typename To, typename From>
To truncate(From x) {
    return saturate<To>(std::trunc(x));
}

} // namespace eposp::vm::detail
