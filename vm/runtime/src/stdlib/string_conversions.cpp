// IEC 61131-3 (3rd ed.) 6.6.2.5.6 table 22-27: conversions between STRING and every elementary
// type, as <TYPE>_TO_STRING(dst, value) and STRING_TO_<TYPE>(text). Integers that do not fit
// the target type wrap like the integer conversion opcodes; unreadable text gives 0, as on
// CODESYS. BYTE..LWORD print in decimal, as CODESYS's BYTE_TO_STRING does.

#include "library_parts.hpp"
#include "string_arguments.hpp"
#include "value_text.hpp"

#include <string>

namespace eposp::vm::stdlib {
namespace {

using S = Scalar;

enum class TextForm : std::uint8_t {
    Bool,
    Signed,
    Unsigned,
    Real,
    Time,
    LongTime,
    Date,
    TimeOfDay,
    DateAndTime
};

/// A type the conversions to and from STRING cover; its scalar is the manifest's.
struct ElementaryType {
    NativeType type;
    TextForm form;
    Scalar scalar() const { return native_scalar(type); }
};

constexpr ElementaryType kTypes[] = {
    {NativeType::Bool, TextForm::Bool},           {NativeType::Sint, TextForm::Signed},
    {NativeType::Int, TextForm::Signed},          {NativeType::Dint, TextForm::Signed},
    {NativeType::Lint, TextForm::Signed},         {NativeType::Usint, TextForm::Unsigned},
    {NativeType::Uint, TextForm::Unsigned},       {NativeType::Udint, TextForm::Unsigned},
    {NativeType::Ulint, TextForm::Unsigned},      {NativeType::Byte, TextForm::Unsigned},
    {NativeType::Word, TextForm::Unsigned},       {NativeType::Dword, TextForm::Unsigned},
    {NativeType::Lword, TextForm::Unsigned},      {NativeType::Real, TextForm::Real},
    {NativeType::Lreal, TextForm::Real},          {NativeType::Time, TextForm::Time},
    {NativeType::Ltime, TextForm::LongTime},      {NativeType::Date, TextForm::Date},
    {NativeType::TimeOfDay, TextForm::TimeOfDay}, {NativeType::DateAndTime, TextForm::DateAndTime},
};

/// Parameter `index` of an integer or BOOL scalar, zero-extended to 64 bits.
std::uint64_t raw_parameter(const NativeArgs& args, std::size_t index, Scalar scalar) {
    switch (scalar_size(scalar)) {
    case 1:
        return args.get<std::uint8_t>(index);
    case 2:
        return args.get<std::uint16_t>(index);
    case 4:
        return args.get<std::uint32_t>(index);
    default:
        return args.get<std::uint64_t>(index);
    }
}

std::int64_t sign_extend(std::uint64_t raw, Scalar scalar) {
    const auto unused_bits = 64 - 8 * scalar_size(scalar);
    return static_cast<std::int64_t>(raw << unused_bits) >> unused_bits;
}

void format_parameter(ValueText& out, const NativeArgs& args, const ElementaryType& type) {
    const auto raw = [&] {
        return raw_parameter(args, 1, type.scalar());
    };
    const auto time = [&] {
        return args.get<std::int64_t>(1);
    };
    switch (type.form) {
    case TextForm::Bool:
        out.append(raw() != 0 ? "TRUE" : "FALSE");
        return;
    case TextForm::Signed:
        return format_signed(out, sign_extend(raw(), type.scalar()));
    case TextForm::Unsigned:
        return format_unsigned(out, raw());
    case TextForm::Real:
        return type.scalar() == S::F32 ? format_real(out, args.get<float>(1), true)
                                       : format_real(out, args.get<double>(1), false);
    case TextForm::Time:
        return format_duration(out, time(), "T#");
    case TextForm::LongTime:
        return format_duration(out, time(), "LTIME#");
    case TextForm::Date:
        return format_date(out, time());
    case TextForm::TimeOfDay:
        return format_time_of_day(out, time());
    case TextForm::DateAndTime:
        return format_date_and_time(out, time());
    }
}

/// The integer value of `text` read in `form` (reals are handled apart).
std::int64_t parse_integral(std::string_view text, TextForm form) {
    switch (form) {
    case TextForm::Bool:
        return parse_bool(text) ? 1 : 0;
    case TextForm::Time:
    case TextForm::LongTime:
        return parse_duration(text);
    case TextForm::Date:
        return parse_date(text);
    case TextForm::TimeOfDay:
        return parse_time_of_day(text);
    case TextForm::DateAndTime:
        return parse_date_and_time(text);
    default:
        return parse_integer(text);
    }
}

void set_integral_result(NativeArgs& args, Scalar scalar, std::int64_t value) {
    const auto raw = static_cast<std::uint64_t>(value);
    switch (scalar_size(scalar)) {
    case 1:
        return args.set_result(static_cast<std::uint8_t>(raw));
    case 2:
        return args.set_result(static_cast<std::uint16_t>(raw));
    case 4:
        return args.set_result(static_cast<std::uint32_t>(raw));
    default:
        return args.set_result(raw);
    }
}

void parse_into_result(NativeArgs& args, std::string_view text, const ElementaryType& type) {
    if (type.scalar() == S::F32) {
        args.set_result(static_cast<float>(parse_real(text)));
    } else if (type.scalar() == S::F64) {
        args.set_result(parse_real(text));
    } else {
        set_integral_result(args, type.scalar(), parse_integral(text, type.form));
    }
}

} // namespace

void register_string_conversions(NativeRegistry& registry) {
    for (const auto& type : kTypes) {
        add_standard(registry, to_text_binding(type.type, CharWidth::Narrow),
                     [&type](NativeArgs& args) {
                         ValueText text;
                         format_parameter(text, args, type);
                         store_string(args, 0, text.view());
                     });
        add_standard(registry, from_text_binding(type.type, CharWidth::Narrow),
                     [&type](NativeArgs& args) {
                         if (const auto text = string_parameter(args, 0)) {
                             parse_into_result(args, *text, type);
                         }
                     });
    }
}

} // namespace eposp::vm::stdlib
