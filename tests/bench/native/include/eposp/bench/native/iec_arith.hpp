#pragma once

// Integer semantics of the reference results (../shared/bench/README.md): DINT arithmetic wraps
// around in two's complement, which C++ signed arithmetic leaves undefined, so the translations
// use these helpers for every DINT +, -, *. INT and shorter operands are evaluated in 32 bits
// (C's integer promotion) and narrowed only when stored or passed: strings.st computes
// (n * i) MOD 1000 on INTs with n * i above 32767, and the table's result needs the unwrapped
// product.

#include <cmath>
#include <concepts>
#include <cstdint>
#include <type_traits>

namespace eposp::bench::native {

// DINT and LINT: the types that are not promoted.
template <typename T>
concept WrappingInteger = std::signed_integral<T> &&(sizeof(T) >= sizeof(int));

// C++20 defines the narrowing conversion to a signed type as modulo 2^N.
template <WrappingInteger T>
constexpr T wrap_add(T a, T b) {
    using U = std::make_unsigned_t<T>;
    return static_cast<T>(static_cast<U>(a) + static_cast<U>(b));
}

template <WrappingInteger T>
constexpr T wrap_sub(T a, T b) {
    using U = std::make_unsigned_t<T>;
    return static_cast<T>(static_cast<U>(a) - static_cast<U>(b));
}

template <WrappingInteger T>
constexpr T wrap_mul(T a, T b) {
    using U = std::make_unsigned_t<T>;
    return static_cast<T>(static_cast<U>(a) * static_cast<U>(b));
}

template <WrappingInteger T>
constexpr T wrap_neg(T a) {
    return wrap_sub(T{0}, a);
}

// LIMIT(MN, IN, MX), IEC 61131-3 selection functions: IN clamped to [MN, MX].
template <typename T>
constexpr T limit(T mn, T in, T mx) {
    return in < mn ? mn : (in > mx ? mx : in);
}

// LREAL_TO_DINT rounds to the nearest integer (IEC 61131-3 type conversion: rounding as IEC
// 60559, ties to even), unlike TRUNC; the value is taken modulo 2^32 like the integer conversions.
inline std::int32_t lreal_to_dint(double value) {
    return static_cast<std::int32_t>(std::llrint(value));
}

} // namespace eposp::bench::native
