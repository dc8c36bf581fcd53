// IEC 61131-3 (3rd ed.) 6.6.2.5.6 table 22-27: conversions between STRING and every elementary
// type, as <TYPE>_TO_STRING(dst, value) and STRING_TO_<TYPE>(text), in the text forms of
// value_text.hpp (which the compiler folds constants with). Integers that do not fit the target
// type wrap like the integer conversion opcodes; unreadable text gives 0, as on CODESYS.

#include "eposp/vm/stdlib/value_text.hpp"
#include "library_parts.hpp"
#include "string_arguments.hpp"

#include <string>

namespace eposp::vm::stdlib {
namespace {

using S = Scalar;

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

void format_parameter(ValueText& out, const NativeArgs& args, const TypeTextForm& type) {
    const Scalar scalar = native_scalar(type.type);
    if (type.form == TextForm::Real) {
        return scalar == S::F32 ? format_real(out, args.get<float>(1), true)
                                : format_real(out, args.get<double>(1), false);
    }
    const std::uint64_t raw = raw_parameter(args, 1, scalar);
    format_value(out, type.form,
                 type.form == TextForm::Signed ? sign_extend(raw, scalar)
                                               : static_cast<std::int64_t>(raw));
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

void parse_into_result(NativeArgs& args, std::string_view text, const TypeTextForm& type) {
    const Scalar scalar = native_scalar(type.type);
    if (scalar == S::F32) {
        args.set_result(static_cast<float>(parse_real(text)));
    } else if (scalar == S::F64) {
        args.set_result(parse_real(text));
    } else {
        set_integral_result(args, scalar, parse_value(text, type.form));
    }
}

} // namespace

void register_string_conversions(NativeRegistry& registry) {
    for (const auto& type : kTextForms) {
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
