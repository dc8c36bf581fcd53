#pragma once

// IEC 61131-3 (3rd ed.) 6.6.2.5.12, table 43: what the character string functions compute from
// their inputs, on the character type (`char` for STRING, `char16_t` for WSTRING). Positions are
// 1-based and count characters. Where the standard leaves out-of-range arguments open, the
// result is the part of the request that exists (CODESYS behaves so for LEFT/RIGHT/MID): lengths
// below 0 count as 0, lengths past the end are cut, and a position outside the string selects
// nothing (MID, DELETE, REPLACE) or is clamped to the nearest end (INSERT). A result is the
// pieces it is made of, in order, not yet cut at any capacity: the VM's natives store them into
// their destination (string_functions.cpp), the compiler folds a call of constants with the
// same ones.

#include <algorithm>
#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace eposp::vm::stdlib {

template <typename Char>
using Text = std::basic_string_view<Char>;

/// A result in up to three consecutive pieces.
template <typename Char>
using TextPieces = std::array<Text<Char>, 3>;

/// `count` clamped to 0..limit.
inline std::size_t clamp_count(std::int32_t count, std::size_t limit) {
    return count <= 0 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(count), limit);
}

/// The 0-based index of 1-based position `position` if it names a character of `text`.
template <typename Char>
std::optional<std::size_t> index_of(Text<Char> text, std::int32_t position) {
    if (position < 1 || static_cast<std::size_t>(position) > text.size()) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(position - 1);
}

/// LEFT(IN, L)
template <typename Char>
Text<Char> left_of(Text<Char> in, std::int32_t length) {
    return in.substr(0, clamp_count(length, in.size()));
}

/// RIGHT(IN, L)
template <typename Char>
Text<Char> right_of(Text<Char> in, std::int32_t length) {
    return in.substr(in.size() - clamp_count(length, in.size()));
}

/// MID(IN, L, P)
template <typename Char>
Text<Char> mid_of(Text<Char> in, std::int32_t length, std::int32_t position) {
    const auto start = index_of(in, position);
    return start ? in.substr(*start, clamp_count(length, in.size() - *start)) : Text<Char>{};
}

/// CONCAT(IN1, IN2); an n-ary CONCAT is these folded left to right.
template <typename Char>
TextPieces<Char> concat_of(Text<Char> a, Text<Char> b) {
    return {a, b, {}};
}

/// INSERT(IN1, IN2, P): IN2 after the first P characters of IN1; P is clamped to 0..LEN(IN1).
template <typename Char>
TextPieces<Char> insert_of(Text<Char> in, Text<Char> insert, std::int32_t position) {
    const auto split = clamp_count(position, in.size());
    return {in.substr(0, split), insert, in.substr(split)};
}

/// REPLACE(IN1, IN2, L, P): `in` with `length` characters from `position` replaced by
/// `insert`; DELETE(IN, L, P) is this with nothing inserted.
template <typename Char>
TextPieces<Char> replace_of(Text<Char> in, Text<Char> insert, std::int32_t length,
                            std::int32_t position) {
    const auto start = index_of(in, position);
    if (!start) {
        return {in, {}, {}};
    }
    return {in.substr(0, *start), insert,
            in.substr(*start + clamp_count(length, in.size() - *start))};
}

/// FIND(IN1, IN2): the 1-based position of the first IN2 in IN1; 0 when it is not there or
/// IN2 is empty.
template <typename Char>
std::int32_t find_in(Text<Char> haystack, Text<Char> needle) {
    if (needle.empty()) {
        return 0;
    }
    const auto at = haystack.find(needle);
    return at == Text<Char>::npos ? 0 : static_cast<std::int32_t>(at + 1);
}

/// The order EQ_STRING, LT_STRING... compare texts in: lexicographic on the character codes as
/// unsigned numbers, as CODESYS compares (char_traits compares char as unsigned char and
/// char16_t as an unsigned 16-bit code).
template <typename Char>
std::strong_ordering text_order(Text<Char> a, Text<Char> b) {
    return a.compare(b) <=> 0;
}

/// STRING_TO_CHAR(IN), WSTRING_TO_WCHAR: the code of the first character, 0 when there is none
/// (as CODESYS).
template <typename Char>
Char first_character(Text<Char> text) {
    return text.empty() ? Char{0} : text.front();
}

/// WSTRING_TO_STRING of one UTF-16 unit: STRING characters are Latin-1 (CODESYS's default code
/// page), a unit above 255 has none and becomes '?', as in CODESYS.
inline char narrow_character(char16_t unit) {
    return unit <= 0xFF ? static_cast<char>(unit) : '?';
}

/// STRING_TO_WSTRING of one Latin-1 character.
inline char16_t wide_character(char c) {
    return static_cast<char16_t>(static_cast<unsigned char>(c));
}

} // namespace eposp::vm::stdlib
