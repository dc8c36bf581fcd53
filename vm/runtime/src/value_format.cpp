#include "eposp/vm/value_format.hpp"

#include "eposp/vm/stdlib/string_layout.hpp"
#include "eposp/vm/stdlib/value_text.hpp"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>
#include <optional>
#include <utility>

namespace eposp::vm {
namespace {

template <typename T>
T load(std::span<const std::uint8_t> memory, std::uint32_t offset) {
    T value;
    std::memcpy(&value, memory.data() + offset, sizeof(T));
    return value;
}

// The times and dates are all I64 nanoseconds (vm/README.md): the type's name says which.
std::optional<stdlib::TextForm> time_form(std::string_view type) {
    using F = stdlib::TextForm;
    static constexpr std::pair<std::string_view, F> kForms[] = {
        {"TIME", F::Time},
        {"LTIME", F::LongTime},
        {"DATE", F::Date},
        {"LDATE", F::LongDate},
        {"TIME_OF_DAY", F::TimeOfDay},
        {"TOD", F::TimeOfDay},
        {"LTIME_OF_DAY", F::LongTimeOfDay},
        {"LTOD", F::LongTimeOfDay},
        {"DATE_AND_TIME", F::DateAndTime},
        {"DT", F::DateAndTime},
        {"LDATE_AND_TIME", F::LongDateAndTime},
        {"LDT", F::LongDateAndTime},
    };
    for (const auto& [name, form] : kForms) {
        if (name == type) {
            return form;
        }
    }
    return std::nullopt;
}

void format_time_value(stdlib::ValueText& out, std::string_view type, std::int64_t ns) {
    if (const auto form = time_form(type)) {
        stdlib::format_value(out, *form, ns);
    } else {
        stdlib::format_signed(out, ns);
    }
}

std::string format_scalar(const TypeDescriptor& type, std::span<const std::uint8_t> memory,
                          std::uint32_t offset) {
    stdlib::ValueText out;
    switch (type.scalar) {
    case Scalar::Bool:
        return load<std::uint8_t>(memory, offset) != 0 ? "TRUE" : "FALSE";
    case Scalar::I8:
        stdlib::format_signed(out, load<std::int8_t>(memory, offset));
        break;
    case Scalar::I16:
        stdlib::format_signed(out, load<std::int16_t>(memory, offset));
        break;
    case Scalar::I32:
        stdlib::format_signed(out, load<std::int32_t>(memory, offset));
        break;
    case Scalar::I64:
        format_time_value(out, type.name, load<std::int64_t>(memory, offset));
        break;
    case Scalar::U8:
        stdlib::format_unsigned(out, load<std::uint8_t>(memory, offset));
        break;
    case Scalar::U16:
        stdlib::format_unsigned(out, load<std::uint16_t>(memory, offset));
        break;
    case Scalar::U32:
        stdlib::format_unsigned(out, load<std::uint32_t>(memory, offset));
        break;
    case Scalar::U64:
    case Scalar::Ptr:
        stdlib::format_unsigned(out, load<std::uint64_t>(memory, offset));
        break;
    case Scalar::F32:
        stdlib::format_real(out, load<float>(memory, offset), true);
        break;
    case Scalar::F64:
        stdlib::format_real(out, load<double>(memory, offset), false);
        break;
    }
    return std::string(out.view());
}

// One character inside a literal quoted by `'` (narrow) or `"` (wide): IEC 61131-3 6.3.3's
// $$ and $' (or $"), and characters outside printable ASCII as $hh / $hhhh.
void append_literal_character(std::string& text, unsigned code, bool wide) {
    const unsigned quote = wide ? '"' : '\'';
    if (code == '$' || code == quote) {
        text += '$';
    }
    if (code < 0x20 || code > 0x7E) {
        text += wide ? fmt::format("${:04X}", code) : fmt::format("${:02X}", code);
    } else {
        text += static_cast<char>(code);
    }
}

std::string format_string(const TypeDescriptor& type, std::span<const std::uint8_t> memory,
                          std::uint32_t offset) {
    const bool wide = type.name.starts_with("WSTRING");
    const char quote = wide ? '"' : '\'';
    const auto length =
        std::min(load<std::uint16_t>(memory, offset), load<std::uint16_t>(memory, offset + 2));
    std::string text(1, quote);
    for (std::uint32_t i = 0; i < length; ++i) {
        const std::uint32_t at = offset + stdlib::kStringHeaderSize + (wide ? 2 * i : i);
        append_literal_character(
            text, wide ? load<std::uint16_t>(memory, at) : load<std::uint8_t>(memory, at), wide);
    }
    return text + quote;
}

// CHAR and WCHAR (U8 / U16 codes) as a one-character literal, like a STRING / WSTRING.
std::string format_character(const TypeDescriptor& type, std::span<const std::uint8_t> memory,
                             std::uint32_t offset) {
    const bool wide = type.name == "WCHAR";
    const char quote = wide ? '"' : '\'';
    std::string text(1, quote);
    append_literal_character(
        text, wide ? load<std::uint16_t>(memory, offset) : load<std::uint8_t>(memory, offset),
        wide);
    return text + quote;
}

// An enumeration's value by its name (`Travel`, as CODESYS shows it), or the number if it names
// none.
std::string format_enumerated(const TypeDescriptor& type, std::span<const std::uint8_t> memory,
                              std::uint32_t offset) {
    const std::int64_t value = integer_value(type.scalar, memory.subspan(offset, type.size));
    for (const Enumerator& enumerator : type.enumerators) {
        if (enumerator.value == value) {
            return enumerator.name;
        }
    }
    return format_scalar(type, memory, offset);
}

} // namespace

std::string format_value(const TypeDescriptor& type, std::span<const std::uint8_t> bytes) {
    switch (type.kind) {
    case TypeKind::Elementary:
        if (type.name == "CHAR" || type.name == "WCHAR") {
            return format_character(type, bytes, 0);
        }
        if (!type.enumerators.empty()) {
            return format_enumerated(type, bytes, 0);
        }
        return format_scalar(type, bytes, 0);
    case TypeKind::String:
        return format_string(type, bytes, 0);
    case TypeKind::Array:
    case TypeKind::Struct:
        break;
    }
    return "<" + type.name + ">";
}

std::string format_value(const Image& image, std::span<const std::uint8_t> memory,
                         VariableLocation location) {
    return format_value(image.types.at(location.type), memory.subspan(location.offset));
}

} // namespace eposp::vm
