#include "object_value.hpp"

#include "terminal_text.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <fmt/format.h>
#include <limits>

namespace eposp::device::cli {
namespace {

struct NamedType {
    std::string_view name;
    ValueType type;
    std::size_t size; ///< bytes; 0: any length
    bool is_signed;
};
constexpr std::array<NamedType, 8> kTypes{{
    {"u8", ValueType::U8, 1, false},
    {"u16", ValueType::U16, 2, false},
    {"u32", ValueType::U32, 4, false},
    {"i8", ValueType::I8, 1, true},
    {"i16", ValueType::I16, 2, true},
    {"i32", ValueType::I32, 4, true},
    {"str", ValueType::Str, 0, false},
    {"hex", ValueType::Hex, 0, false},
}};

const NamedType& named(ValueType type) {
    return kTypes[static_cast<std::size_t>(type)];
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
    const bool negative = text.starts_with('-');
    if (negative) {
        text.remove_prefix(1);
    }
    int base = 10;
    if (text.starts_with("0x") || text.starts_with("0X")) {
        text.remove_prefix(2);
        base = 16;
    }
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, base);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size() ||
        value > std::uint64_t{1} << 32) {
        return std::nullopt;
    }
    return negative ? -static_cast<std::int64_t>(value) : static_cast<std::int64_t>(value);
}

} // namespace

std::optional<ValueType> parse_value_type(std::string_view name) {
    for (const NamedType& entry : kTypes) {
        if (entry.name == name) {
            return entry.type;
        }
    }
    return std::nullopt;
}

std::vector<std::string> value_type_names() {
    std::vector<std::string> names;
    for (const NamedType& entry : kTypes) {
        names.emplace_back(entry.name);
    }
    return names;
}

ValueType value_type_of(canopen::DataType type) {
    using canopen::DataType;
    switch (type) {
    case DataType::Boolean:
    case DataType::Unsigned8:
        return ValueType::U8;
    case DataType::Unsigned16:
        return ValueType::U16;
    case DataType::Unsigned32:
        return ValueType::U32;
    case DataType::Integer8:
        return ValueType::I8;
    case DataType::Integer16:
        return ValueType::I16;
    case DataType::Integer32:
        return ValueType::I32;
    case DataType::VisibleString:
        return ValueType::Str;
    default:
        return ValueType::Hex;
    }
}

bool fits_one_request(ValueType type) {
    return named(type).size != 0;
}

std::string format_value(ValueType type, std::span<const std::uint8_t> bytes) {
    const NamedType& entry = named(type);
    if (type == ValueType::Str) {
        return terminal_text(
            std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    }
    if (type == ValueType::Hex) {
        std::string text;
        for (const std::uint8_t byte : bytes) {
            text += fmt::format("{}{:02x}", text.empty() ? "" : " ", byte);
        }
        return text;
    }
    std::uint64_t raw = 0;
    for (std::size_t i = 0; i < entry.size && i < bytes.size(); ++i) {
        raw |= std::uint64_t{bytes[i]} << (8 * i);
    }
    const unsigned bits = static_cast<unsigned>(8 * entry.size);
    if (entry.is_signed) {
        const std::uint64_t sign = std::uint64_t{1} << (bits - 1);
        const auto value = static_cast<std::int64_t>(raw ^ sign) - static_cast<std::int64_t>(sign);
        return fmt::format("{}", value);
    }
    return fmt::format("{} (0x{:0{}X})", raw, raw, entry.size * 2);
}

core::Result<std::vector<std::uint8_t>> encode_value(ValueType type, std::string_view text) {
    const NamedType& entry = named(type);
    if (type == ValueType::Str) {
        return std::vector<std::uint8_t>(text.begin(), text.end());
    }
    if (type == ValueType::Hex) {
        std::vector<std::uint8_t> bytes;
        std::string digits;
        for (const char c : text) {
            if (c != ' ') {
                digits += c;
            }
        }
        const auto refused = [&] {
            return core::Error{
                fmt::format("'{}' is not hexadecimal bytes (e.g. 01 02 ff)", terminal_text(text))};
        };
        if (digits.size() % 2 != 0) {
            return refused();
        }
        for (std::size_t i = 0; i < digits.size(); i += 2) {
            std::uint8_t byte = 0;
            const char* last = digits.data() + i + 2;
            const auto [end, error] = std::from_chars(digits.data() + i, last, byte, 16);
            if (error != std::errc{} || end != last) {
                return refused();
            }
            bytes.push_back(byte);
        }
        return bytes;
    }
    const auto value = parse_integer(text);
    // CiA 301's signatures of 0x1010 / 0x1011 ("save", "load") and the EPOS P's "eras" are four
    // letters stored as a 32-bit value, first letter in the low byte.
    if (!value && type == ValueType::U32 && text.size() == 4 &&
        std::ranges::all_of(text,
                            [](char c) { return std::isalpha(static_cast<unsigned char>(c)); })) {
        return std::vector<std::uint8_t>(text.begin(), text.end());
    }
    const unsigned bits = static_cast<unsigned>(8 * entry.size);
    const std::int64_t lowest = entry.is_signed ? -(std::int64_t{1} << (bits - 1)) : 0;
    const std::int64_t highest =
        entry.is_signed ? (std::int64_t{1} << (bits - 1)) - 1 : (std::int64_t{1} << bits) - 1;
    if (!value || *value < lowest || *value > highest) {
        return core::Error{fmt::format("'{}' is not a {} value ({} to {})", terminal_text(text),
                                       entry.name, lowest, highest)};
    }
    std::vector<std::uint8_t> bytes(entry.size);
    for (std::size_t i = 0; i < entry.size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(static_cast<std::uint64_t>(*value) >> (8 * i));
    }
    return bytes;
}

std::optional<std::uint32_t> parse_unsigned(std::string_view text, std::uint32_t highest) {
    const auto value = parse_integer(text);
    if (!value || *value < 0 || *value > highest) {
        return std::nullopt;
    }
    return static_cast<std::uint32_t>(*value);
}

} // namespace eposp::device::cli
