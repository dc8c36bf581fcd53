#pragma once

// How IEC 61131-3 STRING[n] and WSTRING[n] variables are laid out in VM memory (vm/README.md,
// "Strings"). A 4-byte header holds the capacity n and the current length, so LEN, assignment
// and truncation at the capacity never scan for the terminator, and a native function can check
// any string pointer it is handed against its own header before touching it.
//
//   offset 0  u16 capacity n (declared length, 1..kMaxStringCapacity)
//   offset 2  u16 current length (<= n)
//   offset 4  n character units (bytes for STRING, UTF-16 units for WSTRING), then one NUL unit
//
// Alignment 2. Assigning a string of the same declared type is one MovN of string_size bytes;
// assigning between capacities goes through the ASSIGN natives, which truncate.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace eposp::vm::stdlib {

inline constexpr std::uint32_t kStringHeaderSize = 4;
inline constexpr std::uint32_t kStringAlign = 2;
/// So that a length or position fits the INT that LEN, FIND, LEFT, MID, ... count in (IEC
/// 61131-3 table 43, as CODESYS and TwinCAT declare them).
inline constexpr std::uint32_t kMaxStringCapacity = 0x7FFF;
/// IEC 61131-3 leaves the length of a bare `STRING` to the implementer; CODESYS uses 80.
inline constexpr std::uint32_t kDefaultStringCapacity = 80;

enum class CharWidth : std::uint8_t { Narrow = 1, Wide = 2 };

/// Bytes a STRING[capacity] (Narrow) or WSTRING[capacity] (Wide) occupies.
constexpr std::uint32_t string_size(std::uint32_t capacity, CharWidth width = CharWidth::Narrow) {
    return kStringHeaderSize + (capacity + 1) * static_cast<std::uint32_t>(width);
}

/// The initial bytes of a STRING[capacity] holding `text` (cut at the capacity), for
/// Builder::initialise or Builder::constant.
std::vector<std::uint8_t> string_image(std::uint32_t capacity, std::string_view text);
/// The same for WSTRING[capacity] holding UTF-16 units.
std::vector<std::uint8_t> wstring_image(std::uint32_t capacity, std::u16string_view text);

/// The text of the STRING at the start of `bytes`, if its header is consistent and it fits.
std::optional<std::string_view> read_string(std::span<const std::uint8_t> bytes);
/// The capacity stored in the header at the start of `bytes`, if the whole string fits in them.
std::optional<std::uint16_t> string_capacity(std::span<const std::uint8_t> bytes,
                                             CharWidth width = CharWidth::Narrow);

/// Stores `text` into the STRING whose header starts `bytes` (its capacity already set), cut at
/// the capacity; returns the length stored. `text` may overlap `bytes`.
std::uint16_t write_string(std::span<std::uint8_t> bytes, std::string_view text);
/// The same for a WSTRING; `text` lies outside `bytes` (VM memory holds bytes, so UTF-16 units
/// are copied in and out, never viewed in place).
std::uint16_t write_wstring(std::span<std::uint8_t> bytes, std::u16string_view text);

/// The current length in characters of the STRING or WSTRING whose consistent header starts
/// `bytes`.
std::uint16_t string_length(std::span<const std::uint8_t> bytes);
/// Character `i` (< string_length) of the WSTRING whose header starts `bytes`.
char16_t wstring_unit(std::span<const std::uint8_t> bytes, std::size_t i);

} // namespace eposp::vm::stdlib
