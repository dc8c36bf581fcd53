#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::compiler::utf8 {

/// Decodes the code point starting at `position` and advances past it. An invalid or truncated
/// sequence yields nothing and advances by one byte, so that every byte is visited once.
std::optional<char32_t> decode(std::string_view text, std::size_t& position);

/// `text` read as Windows-1252 (CODESYS's export encoding, a superset of Latin-1), in UTF-8.
/// Its five unassigned bytes (0x81, 0x8D, 0x8F, 0x90, 0x9D) become the C1 controls of the same
/// number, as the WHATWG encoding standard maps them.
std::string from_windows_1252(std::string_view text);

/// Byte offset of the 1-based `column` (in code points) of `line`, clamped to its end.
std::size_t offset_of_column(std::string_view line, std::uint32_t column);

} // namespace eposp::compiler::utf8
