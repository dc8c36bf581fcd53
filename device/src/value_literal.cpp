#include "value_literal.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <iterator>
#include <limits>
#include <optional>

namespace eposp::device {
namespace {

bool same_name(std::string_view a, std::string_view b) {
    return std::ranges::equal(a, b, [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) ==
               std::tolower(static_cast<unsigned char>(y));
    });
}

std::string_view trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
        return {};
    }
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// `INT#42` -> `42`, `Mode#Travel` -> `Travel`; a base prefix (`16#FF`) stays.
std::string_view without_type_prefix(std::string_view text) {
    const auto hash = text.find('#');
    if (hash == std::string_view::npos || hash == 0) {
        return text;
    }
    const std::string_view prefix = text.substr(0, hash);
    const bool is_base = std::ranges::all_of(
        prefix, [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
    return is_base ? text : text.substr(hash + 1);
}

bool is_time_type(std::string_view name) {
    for (const std::string_view time :
         {"TIME", "LTIME", "DATE", "TIME_OF_DAY", "TOD", "DATE_AND_TIME", "DT"}) {
        if (same_name(name, time)) {
            return true;
        }
    }
    return false;
}

// IEC 61131-3 6.3.2: an optional sign, then decimal digits or base#digits, `_` between digits.
std::optional<std::int64_t> parse_integer(std::string_view text, bool& negative) {
    negative = !text.empty() && text.front() == '-';
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
        text.remove_prefix(1);
    }
    int base = 10;
    if (const auto hash = text.find('#'); hash != std::string_view::npos) {
        const std::string_view prefix = text.substr(0, hash);
        if (prefix == "2" || prefix == "8" || prefix == "16") {
            base = prefix == "2" ? 2 : prefix == "8" ? 8 : 16;
            text.remove_prefix(hash + 1);
        } else {
            return std::nullopt;
        }
    }
    std::string digits;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '_' && i > 0 && i + 1 < text.size() && text[i - 1] != '_') {
            continue;
        }
        digits += text[i];
    }
    std::uint64_t magnitude = 0;
    const auto [end, error] =
        std::from_chars(digits.data(), digits.data() + digits.size(), magnitude, base);
    if (digits.empty() || error != std::errc{} || end != digits.data() + digits.size()) {
        return std::nullopt;
    }
    if (negative) {
        if (magnitude > std::uint64_t{1} << 63) {
            return std::nullopt;
        }
        return static_cast<std::int64_t>(0 - magnitude);
    }
    return static_cast<std::int64_t>(magnitude); // a U64 above INT64_MAX wraps; see in_range
}

bool in_range(vm::Scalar scalar, std::int64_t value, bool negative) {
    const unsigned bits = vm::scalar_size(scalar) * 8;
    if (vm::is_signed_integer(scalar)) {
        if (bits == 64) {
            return negative == (value < 0);
        }
        const std::int64_t high = (std::int64_t{1} << (bits - 1)) - 1;
        return value >= -high - 1 && value <= high;
    }
    if (negative) {
        return value == 0;
    }
    return bits == 64 || static_cast<std::uint64_t>(value) < (std::uint64_t{1} << bits);
}

std::vector<std::uint8_t> little_endian(std::uint64_t value, std::uint32_t size) {
    std::vector<std::uint8_t> bytes(size);
    for (std::uint32_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(value >> (8 * i));
    }
    return bytes;
}

core::Result<std::vector<std::uint8_t>> parse_integer_value(const vm::TypeDescriptor& type,
                                                            std::string_view text) {
    for (const vm::Enumerator& enumerator : type.enumerators) {
        if (same_name(enumerator.name, text)) {
            return little_endian(static_cast<std::uint64_t>(enumerator.value), type.size);
        }
    }
    bool negative = false;
    const auto value = parse_integer(text, negative);
    if (!value) {
        return core::Error{fmt::format("'{}' is no {} literal", text, type.name)};
    }
    if (!in_range(type.scalar, *value, negative)) {
        return core::Error{fmt::format("{} is out of the range of {}", text, type.name)};
    }
    return little_endian(static_cast<std::uint64_t>(*value), type.size);
}

core::Result<std::vector<std::uint8_t>> parse_real_value(const vm::TypeDescriptor& type,
                                                         std::string_view text) {
    std::string digits;
    std::ranges::copy_if(text, std::back_inserter(digits), [](char c) { return c != '_'; });
    if (!digits.empty() && digits.front() == '+') {
        digits.erase(0, 1);
    }
    double value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || error != std::errc{} || end != digits.data() + digits.size() ||
        !std::isfinite(value)) {
        return core::Error{fmt::format("'{}' is no {} literal", text, type.name)};
    }
    std::vector<std::uint8_t> bytes(type.size);
    if (type.scalar == vm::Scalar::F32) {
        if (std::fabs(value) > std::numeric_limits<float>::max()) {
            return core::Error{fmt::format("{} is out of the range of {}", text, type.name)};
        }
        const auto single = static_cast<float>(value);
        std::memcpy(bytes.data(), &single, sizeof single);
    } else {
        std::memcpy(bytes.data(), &value, sizeof value);
    }
    return bytes;
}

} // namespace

core::Result<std::vector<std::uint8_t>> parse_value(const vm::TypeDescriptor& type,
                                                    std::string_view text) {
    text = without_type_prefix(trimmed(text));
    if (type.kind != vm::TypeKind::Elementary || type.name == "CHAR" || type.name == "WCHAR" ||
        type.scalar == vm::Scalar::Ptr || is_time_type(type.name)) {
        return core::Error{
            fmt::format("{} values cannot be written as a literal here (numbers, BOOL and "
                        "enumerations can)",
                        type.name)};
    }
    switch (type.scalar) {
    case vm::Scalar::Bool:
        if (same_name(text, "TRUE") || text == "1") {
            return std::vector<std::uint8_t>{1};
        }
        if (same_name(text, "FALSE") || text == "0") {
            return std::vector<std::uint8_t>{0};
        }
        return core::Error{fmt::format("'{}' is no BOOL literal (TRUE or FALSE)", text)};
    case vm::Scalar::F32:
    case vm::Scalar::F64:
        return parse_real_value(type, text);
    default:
        return parse_integer_value(type, text);
    }
}

} // namespace eposp::device
