#include "eds_value.hpp"

#include "ini_document.hpp"
#include "numeric_value.hpp"

#include <charconv>
#include <fmt/format.h>
#include <limits>

namespace eposp::canopen {
namespace {

// One integer literal: its magnitude, its sign, and whether it was written in hex or octal
// (then a signed type may take it as its two's complement bits, as vendor files do).
struct Literal {
    std::uint64_t magnitude = 0;
    bool negative = false;
    bool bit_pattern = false;
};

std::optional<Literal> parse_literal(std::string_view text) {
    Literal literal;
    if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
        literal.negative = text[0] == '-';
        text.remove_prefix(1);
    }
    int base = 10;
    if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        base = 16;
        text.remove_prefix(2);
    } else if (text.size() > 1 && text[0] == '0') {
        base = 8;
        text.remove_prefix(1);
    }
    literal.bit_pattern = base != 10;
    const auto [end, error] =
        std::from_chars(text.data(), text.data() + text.size(), literal.magnitude, base);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return literal;
}

// CiA 306 4.5.2: "$NODEID+0x180", "0x180+$NODEID", "$NODEID" or a plain literal.
core::Result<Literal> parse_integer_expression(std::string_view text,
                                               std::optional<NodeId> node_id) {
    Literal sum;
    bool has_node_id = false;
    std::size_t terms = 0;
    while (true) {
        const auto plus = text.find('+', 1); // a leading '+' is a sign
        const std::string_view term = trim(text.substr(0, plus));
        ++terms;
        if (to_lower(term) == "$nodeid") {
            if (!node_id) {
                return core::Error{"$NODEID needs a node-ID"};
            }
            has_node_id = true;
            sum.magnitude += *node_id;
        } else {
            const auto literal = parse_literal(term);
            if (!literal) {
                return core::Error{fmt::format("'{}' is not a number", term)};
            }
            if (literal->negative && (terms > 1 || plus != std::string_view::npos)) {
                return core::Error{fmt::format("'{}': a sum takes no negative terms", text)};
            }
            if (literal->magnitude > std::numeric_limits<std::uint64_t>::max() - sum.magnitude) {
                return core::Error{"the number is too large"};
            }
            sum.magnitude += literal->magnitude;
            sum.negative = literal->negative;
            sum.bit_pattern = sum.bit_pattern || literal->bit_pattern;
        }
        if (plus == std::string_view::npos) {
            break;
        }
        text.remove_prefix(plus + 1);
    }
    if (has_node_id) {
        sum.bit_pattern = false;
    }
    return sum;
}

std::size_t bits_of(DataType type) {
    return *fixed_size(type) * 8;
}

std::uint64_t width_mask(DataType type) {
    const std::size_t bits = bits_of(type);
    return bits == 64 ? std::numeric_limits<std::uint64_t>::max() : (std::uint64_t{1} << bits) - 1;
}

core::Result<Bytes> out_of_range(DataType type, std::string_view text) {
    return core::Error{fmt::format("'{}' does not fit {}", text, to_string(type))};
}

core::Result<Bytes> integer_value(DataType type, std::string_view text,
                                  std::optional<NodeId> node_id) {
    auto literal = parse_integer_expression(text, node_id);
    if (!literal) {
        return core::Error{literal.error()};
    }
    std::optional<Bytes> bytes;
    if (is_signed_integer(type) && literal->bit_pattern && !literal->negative &&
        literal->magnitude <= width_mask(type)) {
        bytes = encode_numeric(DataType::Unsigned64, literal->magnitude);
        bytes->resize(*fixed_size(type));
    } else if (literal->negative) {
        if (literal->magnitude > std::uint64_t{1} << 63) {
            return out_of_range(type, text);
        }
        bytes = encode_numeric(type, static_cast<std::int64_t>(0 - literal->magnitude));
    } else {
        bytes = encode_numeric(type, literal->magnitude);
    }
    if (!bytes) {
        return out_of_range(type, text);
    }
    return *bytes;
}

// A TIME_OF_DAY or TIME_DIFFERENCE: its 48 bits as one unsigned number.
core::Result<Bytes> time_value(DataType type, std::string_view text) {
    const auto value = parse_eds_unsigned(text);
    if (!value || *value > width_mask(type)) {
        return out_of_range(type, text);
    }
    Bytes bytes = encode(*value);
    bytes.resize(*fixed_size(type));
    return bytes;
}

core::Result<Bytes> real_value(DataType type, std::string_view text) {
    if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        const auto bits = parse_eds_unsigned(text);
        if (!bits || *bits > width_mask(type)) {
            return out_of_range(type, text);
        }
        Bytes bytes = encode(*bits);
        bytes.resize(*fixed_size(type));
        return bytes;
    }
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (text.starts_with('+')) {
        ++first; // from_chars takes no plus sign
    }
    if (type == DataType::Real32) {
        float value = 0;
        const auto [end, error] = std::from_chars(first, last, value);
        if (text.empty() || error != std::errc{} || end != last) {
            return core::Error{fmt::format("'{}' is not a REAL32", text)};
        }
        return encode(value);
    }
    double value = 0;
    const auto [end, error] = std::from_chars(first, last, value);
    if (text.empty() || error != std::errc{} || end != last) {
        return core::Error{fmt::format("'{}' is not a REAL64", text)};
    }
    return encode(value);
}

core::Result<Bytes> hex_pairs(DataType type, std::string_view text) {
    Bytes bytes;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        std::uint8_t byte = 0;
        const auto [end, error] =
            std::from_chars(text.data() + i, text.data() + std::min(i + 2, text.size()), byte, 16);
        if (error != std::errc{} || end != text.data() + i + 2) {
            return core::Error{
                fmt::format("'{}' is not a {} in hex byte pairs", text, to_string(type))};
        }
        bytes.push_back(byte);
        i += 2;
    }
    return bytes;
}

std::uint64_t raw_unsigned(std::span<const std::uint8_t> value) {
    std::uint64_t raw = 0;
    for (std::size_t i = 0; i < value.size(); ++i) {
        raw |= std::uint64_t{value[i]} << (8 * i);
    }
    return raw;
}

} // namespace

std::optional<std::uint64_t> parse_eds_unsigned(std::string_view text) {
    const auto literal = parse_literal(trim(text));
    if (!literal || literal->negative) {
        return std::nullopt;
    }
    return literal->magnitude;
}

std::string format_eds_value(DataType type, std::span<const std::uint8_t> value) {
    const auto size = fixed_size(type);
    if (size && value.size() != *size) {
        // Only a read hook can produce this; show the bytes rather than lie about the type.
        return format_eds_value(DataType::OctetString, value);
    }
    switch (type) {
    case DataType::VisibleString: {
        // One INI line holds the value: a line break cannot be written.
        std::string text(value.begin(), value.end());
        for (char& c : text) {
            c = (c == '\r' || c == '\n') ? ' ' : c;
        }
        return text;
    }
    case DataType::OctetString:
    case DataType::UnicodeString:
    case DataType::Domain: {
        std::string text;
        for (const std::uint8_t byte : value) {
            text += fmt::format("{:02X}", byte);
        }
        return text;
    }
    case DataType::TimeOfDay:
    case DataType::TimeDifference:
        return fmt::format("0x{:0{}X}", raw_unsigned(value), *size * 2);
    case DataType::Real32:
        return fmt::format("{}", decode<float>(value));
    case DataType::Real64:
        return fmt::format("{}", decode<double>(value));
    case DataType::Boolean:
        return fmt::format("{}", raw_unsigned(value));
    default:
        break;
    }
    const NumericValue number = *decode_numeric(type, value);
    if (const auto* i = std::get_if<std::int64_t>(&number)) {
        return fmt::format("{}", *i);
    }
    return fmt::format("0x{:0{}X}", std::get<std::uint64_t>(number), *size * 2);
}

core::Result<Bytes> parse_eds_value(DataType type, std::string_view text,
                                    std::optional<NodeId> node_id) {
    if (type == DataType::VisibleString) {
        return encode_string(text);
    }
    if (!fixed_size(type)) {
        return hex_pairs(type, trim(text));
    }
    text = trim(text);
    if (text.empty()) {
        return Bytes(*fixed_size(type), 0); // CiA 306: a missing default is zero
    }
    if (is_real(type)) {
        return real_value(type, text);
    }
    if (type == DataType::TimeOfDay || type == DataType::TimeDifference) {
        return time_value(type, text);
    }
    if (type == DataType::Boolean) {
        if (to_lower(text) == "true") {
            return Bytes{1};
        }
        if (to_lower(text) == "false") {
            return Bytes{0};
        }
    }
    return integer_value(type, text, node_id);
}

} // namespace eposp::canopen
