#pragma once

#include "eposp/canopen/data_type.hpp"
#include "eposp/core/result.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::device::cli {

/// How `eposp od` reads and writes an object's bytes (`--type`).
enum class ValueType { U8, U16, U32, I8, I16, I32, Str, Hex };

std::optional<ValueType> parse_value_type(std::string_view name);
/// The names `--type` accepts, for its help and its check.
std::vector<std::string> value_type_names();
/// How an object of `type` is shown: its integer type, VISIBLE_STRING as text, anything else as
/// hexadecimal bytes.
ValueType value_type_of(canopen::DataType type);
/// Whether the value fits a ReadObject / WriteObject (4 bytes) rather than a segmented transfer.
bool fits_one_request(ValueType type);

/// `405 (0x00000195)`, `-3`, the text, or `01 02 ff`.
std::string format_value(ValueType type, std::span<const std::uint8_t> bytes);
/// The bytes of VALUE as `type`: an integer in decimal or 0x hexadecimal within the type's
/// range (a 32-bit one also as four letters, the store / restore signatures `save`, `load`,
/// `eras`), the text itself, or hexadecimal bytes (`01 02 ff` or `0102ff`).
core::Result<std::vector<std::uint8_t>> encode_value(ValueType type, std::string_view text);

/// A number in decimal or with 0x in `[0, highest]` ("0x1F50", "8016").
std::optional<std::uint32_t> parse_unsigned(std::string_view text, std::uint32_t highest);

} // namespace eposp::device::cli
