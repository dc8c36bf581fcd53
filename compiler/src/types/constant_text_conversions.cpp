// The constants of the conversions to and from STRING and WSTRING (table 22), computed by the
// VM's own functions on the value the native is passed: a number, BOOL or time written in its
// text form and read back from one (vm/stdlib/value_text.hpp), a CHAR or WCHAR made a text of
// one character and taken back as the first one, a text's characters converted one by one
// between STRING and WSTRING (vm/stdlib/text_functions.hpp). A text result is cut at the
// capacity of its type, as code generation's conversion cuts it (STRING[80], WSTRING[80]).

#include "constant_folder.hpp"
#include "eposp/vm/stdlib/text_functions.hpp"
#include "eposp/vm/stdlib/value_text.hpp"

#include <optional>
#include <string>
#include <type_traits>

namespace eposp::compiler::types {

namespace {

namespace stdlib = vm::stdlib;
using E = ast::ElementaryType;

bool is_character(const sema::Type& type) {
    return type.kind == sema::TypeKind::Elementary &&
           (type.elementary == E::Char || type.elementary == E::Wchar);
}

/// A number, BOOL or time as the native takes it: 64 bits, an integer sign- or zero-extended
/// as its type is signed or not (the constant holds it so), a BOOL as 0 or 1, a time in ns.
std::optional<std::int64_t> integral(const Constant& constant) {
    if (const auto* b = std::get_if<bool>(&constant)) {
        return *b ? 1 : 0;
    }
    if (const auto* i = std::get_if<std::int64_t>(&constant)) {
        return *i;
    }
    if (const auto* u = std::get_if<std::uint64_t>(&constant)) {
        return static_cast<std::int64_t>(*u);
    }
    return std::nullopt;
}

/// <TYPE>_TO_STRING of `constant`, a value of `from`.
std::optional<std::string> value_text(const Constant& constant, const sema::Type& from) {
    const auto form = stdlib::text_form(sema::native_type(from));
    if (!form) {
        return std::nullopt; // no such native: refused where it is called
    }
    stdlib::ValueText text;
    if (*form == stdlib::TextForm::Real) {
        const auto* real = std::get_if<double>(&constant);
        if (real == nullptr) {
            return std::nullopt;
        }
        stdlib::format_real(text, *real, sema::scalar_of(from) == vm::Scalar::F32);
    } else {
        const auto value = integral(constant);
        if (!value) {
            return std::nullopt;
        }
        stdlib::format_value(text, *form, *value);
    }
    return std::string(text.view());
}

/// A text's characters converted one by one to the other width (STRING_TO_WSTRING,
/// WSTRING_TO_STRING).
template <typename To, typename From>
std::basic_string<To> other_width(const std::basic_string<From>& text) {
    std::basic_string<To> result;
    for (const From c : text) {
        if constexpr (std::is_same_v<To, char>) {
            result += stdlib::narrow_character(c);
        } else {
            result += stdlib::wide_character(c);
        }
    }
    return result;
}

} // namespace

std::optional<Constant> ConstantFolder::text_conversion(const Constant& constant,
                                                        const sema::Type& from,
                                                        const sema::Type& to) const {
    const auto* narrow = std::get_if<std::string>(&constant);
    const auto* wide = std::get_if<std::u16string>(&constant);
    if (to.kind == sema::TypeKind::String) {
        // The result is cut at its type's capacity, as code generation cuts it wherever it
        // puts the result (also straight into a longer variable).
        const auto cut = [&to](auto text) -> Constant {
            if (text.size() > to.capacity) {
                text.resize(to.capacity);
            }
            return text;
        };
        if (from.kind == sema::TypeKind::String) {
            if (from.wide == to.wide) {
                return narrow != nullptr ? std::optional(cut(*narrow))
                       : wide != nullptr ? std::optional(cut(*wide))
                                         : std::nullopt;
            }
            return narrow != nullptr ? std::optional(cut(other_width<char16_t>(*narrow)))
                   : wide != nullptr ? std::optional(cut(other_width<char>(*wide)))
                                     : std::nullopt;
        }
        if (is_character(from)) {
            // CHAR_TO_STRING, WCHAR_TO_WSTRING: the text of that one character.
            const auto code = integral(constant);
            if (!code) {
                return std::nullopt;
            }
            return to.wide ? Constant(std::u16string(1, static_cast<char16_t>(*code)))
                           : Constant(std::string(1, static_cast<char>(*code)));
        }
        const auto text = value_text(constant, from);
        return text ? std::optional(cut(*text)) : std::nullopt;
    }
    if (is_character(to)) {
        // STRING_TO_CHAR, WSTRING_TO_WCHAR: the code of the first character, as a CHAR literal's.
        if (narrow != nullptr) {
            return std::uint64_t{
                static_cast<unsigned char>(stdlib::first_character<char>(*narrow))};
        }
        return wide != nullptr ? std::optional<Constant>(
                                     std::uint64_t{stdlib::first_character<char16_t>(*wide)})
                               : std::nullopt;
    }
    const auto form = stdlib::text_form(sema::native_type(to));
    if (narrow == nullptr || !form) {
        return std::nullopt;
    }
    if (*form == stdlib::TextForm::Real) {
        const double real = stdlib::parse_real(*narrow);
        return sema::scalar_of(to) == vm::Scalar::F32
                   ? static_cast<double>(static_cast<float>(real))
                   : real;
    }
    const std::int64_t value = stdlib::parse_value(*narrow, *form);
    if (*form == stdlib::TextForm::Bool) {
        return value != 0;
    }
    if (sema::is_time_like(to)) {
        return value; // ns, the constant of every time and date
    }
    // Cut to the type's width as the native's result is.
    return convert(value, types_.elementary(E::Lint), to);
}

} // namespace eposp::compiler::types
