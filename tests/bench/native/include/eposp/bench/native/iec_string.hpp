#pragma once

// IEC 61131-3 STRING: a fixed-capacity single-byte string (STRING[n], n = 80 when not given),
// and the standard character string functions of 3rd edition 6.6.2.5 with 1-based positions. A
// value longer than the capacity of its destination is truncated, as a PLC does.

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace eposp::bench::native {

inline constexpr std::size_t kDefaultStringLength = 80;

template <std::size_t Capacity = kDefaultStringLength>
class IecString {
    static_assert(Capacity <= UINT16_MAX, "STRING[n] holds at most 65535 characters");

public:
    IecString() = default;
    IecString(std::string_view text) // NOLINT(google-explicit-constructor): ST assigns freely
        : length_(static_cast<std::uint16_t>(std::min(text.size(), Capacity))) {
        std::copy_n(text.data(), length_, chars_.data());
    }

    operator std::string_view() const { return {chars_.data(), length_}; }
    std::string_view view() const { return *this; }

private:
    std::uint16_t length_ = 0;
    std::array<char, Capacity> chars_{};
};

using String = IecString<>;

// LEN(IN)
inline std::int16_t len(std::string_view in) {
    return static_cast<std::int16_t>(in.size());
}

// CONCAT(IN1, IN2)
inline String concat(std::string_view in1, std::string_view in2) {
    std::array<char, kDefaultStringLength> joined{};
    const auto first = std::min(in1.size(), joined.size());
    const auto second = std::min(in2.size(), joined.size() - first);
    std::copy_n(in1.data(), first, joined.data());
    std::copy_n(in2.data(), second, joined.data() + first);
    return String{std::string_view{joined.data(), first + second}};
}

// LEFT(IN, L): the first L characters; L beyond the length gives the whole string, L < 0 (an
// error in the standard) gives the empty string.
inline String left(std::string_view in, std::int16_t l) {
    return String{in.substr(0, static_cast<std::size_t>(std::max<std::int16_t>(l, 0)))};
}

// MID(IN, L, P): L characters from position P (1-based). Positions outside 1..LEN(IN) and
// L < 0 (errors in the standard) give the empty string; L is cut at the end of IN.
inline String mid(std::string_view in, std::int16_t l, std::int16_t p) {
    if (p < 1 || static_cast<std::size_t>(p) > in.size() || l < 0) {
        return String{};
    }
    return String{in.substr(static_cast<std::size_t>(p - 1), static_cast<std::size_t>(l))};
}

// FIND(IN1, IN2): 1-based position of the first occurrence of IN2 in IN1, 0 when absent.
inline std::int16_t find(std::string_view in1, std::string_view in2) {
    if (in2.empty()) {
        return 0;
    }
    const auto at = in1.find(in2);
    return at == std::string_view::npos ? std::int16_t{0} : static_cast<std::int16_t>(at + 1);
}

// INT_TO_STRING(IN): the decimal literal of IN, with a leading '-' when negative.
inline String int_to_string(std::int16_t in) {
    // Sized like a STRING rather than the 6 characters needed: GCC 12 cannot see that the
    // copy into the String stays within a smaller buffer and warns (-Warray-bounds).
    std::array<char, kDefaultStringLength> digits;
    const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), in).ptr;
    return String{std::string_view{digits.data(), static_cast<std::size_t>(end - digits.data())}};
}

} // namespace eposp::bench::native
