#pragma once

#include <array>
#include <bit>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace eposp::canopen {

/// A value as CANopen carries it: little-endian bytes (CiA 301 7.1.2).
using Bytes = std::vector<std::uint8_t>;

template <typename T>
concept Arithmetic = std::integral<T> || std::floating_point<T>;

/// The little-endian bytes of an integer or IEEE 754 value, without allocating.
template <Arithmetic T>
std::array<std::uint8_t, sizeof(T)> encode_array(T value) {
    std::array<std::uint8_t, sizeof(T)> bytes{};
    if constexpr (std::is_same_v<T, bool>) {
        bytes[0] = value ? 1 : 0;
    } else {
        using Unsigned = std::make_unsigned_t<
            std::conditional_t<std::is_floating_point_v<T>,
                               std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>, T>>;
        const auto raw = std::bit_cast<Unsigned>(value);
        for (std::size_t i = 0; i < sizeof(T); ++i) {
            bytes[i] = static_cast<std::uint8_t>(raw >> (8 * i));
        }
    }
    return bytes;
}

/// The little-endian bytes of an integer or IEEE 754 value.
template <Arithmetic T>
Bytes encode(T value) {
    const auto bytes = encode_array(value);
    return {bytes.begin(), bytes.end()};
}

/// The value of little-endian bytes; a size other than sizeof(T) is a programming error.
template <Arithmetic T>
T decode(std::span<const std::uint8_t> bytes) {
    if (bytes.size() != sizeof(T)) {
        throw std::invalid_argument("canopen::decode: wrong number of bytes for the type");
    }
    if constexpr (std::is_same_v<T, bool>) {
        return bytes[0] != 0;
    } else {
        using Unsigned = std::make_unsigned_t<
            std::conditional_t<std::is_floating_point_v<T>,
                               std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>, T>>;
        Unsigned raw = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i) {
            raw = static_cast<Unsigned>(raw | static_cast<Unsigned>(bytes[i]) << (8 * i));
        }
        return std::bit_cast<T>(raw);
    }
}

inline Bytes encode_string(std::string_view text) {
    return {text.begin(), text.end()};
}

} // namespace eposp::canopen
