#include "literal_decoder.hpp"

#include "eposp/compiler/ascii_case.hpp"
#include "eposp/vm/stdlib/duration_fraction.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"
#include "../utf8.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <string>

namespace eposp::compiler {

namespace {

using ast::ElementaryType;
using core::Error;
using core::Result;

constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;
constexpr std::int64_t kNanosecondsPerDay = 86'400 * kNanosecondsPerSecond;

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

int digit_value(char c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    const int upper = std::toupper(static_cast<unsigned char>(c));
    return upper >= 'A' && upper <= 'Z' ? upper - 'A' + 10 : 99;
}

// IEC 61131-3 ed. 3, 6.3.2: an underscore may only stand between two digits.
Result<std::uint64_t> parse_digits(std::string_view digits, unsigned base) {
    if (digits.empty()) {
        return Error{"missing digits"};
    }
    if (digits.front() == '_' || digits.back() == '_' ||
        digits.find("__") != std::string_view::npos) {
        return Error{"misplaced '_' in " + quoted(digits) +
                     ": an underscore may only separate digits"};
    }
    std::uint64_t value = 0;
    for (char c : digits) {
        if (c == '_') {
            continue;
        }
        const int digit = digit_value(c);
        if (digit >= static_cast<int>(base)) {
            return Error{quoted(std::string_view(&c, 1)) + " is not a digit in base " +
                         std::to_string(base)};
        }
        if (__builtin_mul_overflow(value, base, &value) ||
            __builtin_add_overflow(value, static_cast<unsigned>(digit), &value)) {
            return Error{"integer literal " + quoted(digits) + " does not fit in 64 bits"};
        }
    }
    return value;
}

Result<std::uint64_t> parse_integer(std::string_view text) {
    const std::size_t hash = text.find('#');
    if (hash == std::string_view::npos) {
        return parse_digits(text, 10);
    }
    const Result<std::uint64_t> base = parse_digits(text.substr(0, hash), 10);
    if (!base) {
        return base;
    }
    if (*base != 2 && *base != 8 && *base != 16) {
        return Error{"base " + std::to_string(*base) + " is not supported; use 2#, 8# or 16#"};
    }
    return parse_digits(text.substr(hash + 1), static_cast<unsigned>(*base));
}

Result<double> parse_real(std::string_view text) {
    std::string plain;
    std::size_t group_start = 0;
    // Check each run of digits (integer part, fraction, exponent) for misplaced underscores.
    for (std::size_t i = 0; i <= text.size(); ++i) {
        if (i == text.size() || text[i] == '.' || text[i] == 'e' || text[i] == 'E') {
            std::string_view group = text.substr(group_start, i - group_start);
            if (!group.empty() && (group.front() == '+' || group.front() == '-')) {
                group.remove_prefix(1);
            }
            if (const auto digits = parse_digits(group, 10); !digits) {
                // A group too long for 64 bits is still a valid real; only syntax errors count.
                if (digits.error().find("64 bits") == std::string::npos) {
                    return Error{digits.error()};
                }
            }
            group_start = i + 1;
        }
        if (i < text.size() && text[i] != '_') {
            plain += text[i];
        }
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(plain.data(), plain.data() + plain.size(), value);
    if (error == std::errc::result_out_of_range || !std::isfinite(value)) {
        return Error{"real literal " + quoted(text) + " is out of the range of LREAL"};
    }
    if (error != std::errc{} || end != plain.data() + plain.size()) {
        return Error{"malformed real literal " + quoted(text)};
    }
    return value;
}

// The literal prefixes of table 8 and 9 that are not type names themselves.
std::optional<ElementaryType> prefix_type(std::string_view prefix) {
    static constexpr std::array<std::pair<std::string_view, ElementaryType>, 4> kShortPrefixes{{
        {"T", ElementaryType::Time},
        {"LT", ElementaryType::Ltime},
        {"D", ElementaryType::Date},
        {"LD", ElementaryType::Ldate},
    }};
    for (const auto& [name, type] : kShortPrefixes) {
        if (equal_ignoring_case(name, prefix)) {
            return type;
        }
    }
    return ast::elementary_type_from_name(prefix);
}

struct Prefixed {
    ElementaryType type;
    std::string_view body;
};

Prefixed split_prefix(std::string_view text) {
    const std::size_t hash = text.find('#');
    return {prefix_type(text.substr(0, hash)).value_or(ElementaryType::Time),
            text.substr(hash + 1)};
}

// IEC 61131-3 ed. 3, 6.3.4, table 8: T#1d2h3m4s5ms6us7ns, optional '_' between the parts, the
// last part may have a fraction, only the most significant part may exceed its natural range.
Result<ast::Literal> decode_duration(std::string_view text) {
    struct Unit {
        std::string_view name;
        std::int64_t nanoseconds;
        std::int64_t limit; // exclusive bound when not the most significant part
    };
    static constexpr std::array<Unit, 7> kUnits{{
        {"d", kNanosecondsPerDay, 0},
        {"h", 3'600 * kNanosecondsPerSecond, 24},
        {"m", 60 * kNanosecondsPerSecond, 60},
        {"s", kNanosecondsPerSecond, 60},
        {"ms", 1'000'000, 1000},
        {"us", 1'000, 1000},
        {"ns", 1, 1000},
    }};
    const auto [type, whole_body] = split_prefix(text);
    std::string_view body = whole_body;
    const bool negative = !body.empty() && body.front() == '-';
    if (!body.empty() && (body.front() == '-' || body.front() == '+')) {
        body.remove_prefix(1);
    }
    std::int64_t total = 0;
    std::size_t previous_unit = 0;
    bool first = true;
    while (!body.empty()) {
        if (!first && body.front() == '_') {
            body.remove_prefix(1);
        }
        std::size_t number_end = 0;
        while (number_end < body.size() &&
               (std::isdigit(static_cast<unsigned char>(body[number_end])) ||
                body[number_end] == '_' || body[number_end] == '.')) {
            ++number_end;
        }
        std::size_t unit_end = number_end;
        while (unit_end < body.size() && std::isalpha(static_cast<unsigned char>(body[unit_end]))) {
            ++unit_end;
        }
        const std::string_view number = body.substr(0, number_end);
        const std::string_view unit_name = body.substr(number_end, unit_end - number_end);
        if (number.empty() || unit_name.empty()) {
            return Error{"malformed duration " + quoted(text) +
                         ": expected a number followed by d, h, m, s, ms, us or ns"};
        }
        std::size_t unit_index = kUnits.size();
        for (std::size_t i = 0; i < kUnits.size(); ++i) {
            if (equal_ignoring_case(kUnits[i].name, unit_name)) {
                unit_index = i;
            }
        }
        if (unit_index == kUnits.size()) {
            return Error{"unknown unit " + quoted(unit_name) + " in duration " + quoted(text) +
                         "; use d, h, m, s, ms, us or ns"};
        }
        if (!first && unit_index <= previous_unit) {
            return Error{"the units of duration " + quoted(text) +
                         " must go from days down to nanoseconds, each at most once"};
        }
        const Unit& unit = kUnits[unit_index];
        const std::size_t dot = number.find('.');
        const Result<std::uint64_t> whole = parse_digits(number.substr(0, dot), 10);
        if (!whole) {
            return Error{whole.error()};
        }
        if (!first && static_cast<std::int64_t>(*whole) >= unit.limit) {
            return Error{"'" + std::to_string(*whole) + std::string(unit_name) + "' in duration " +
                         quoted(text) + " exceeds " + std::to_string(unit.limit - 1) +
                         std::string(unit_name)};
        }
        std::int64_t part = 0;
        if (*whole > static_cast<std::uint64_t>(INT64_MAX) ||
            __builtin_mul_overflow(static_cast<std::int64_t>(*whole), unit.nanoseconds, &part) ||
            __builtin_add_overflow(total, part, &total)) {
            return Error{"duration " + quoted(text) + " is too long for 64-bit nanoseconds"};
        }
        body.remove_prefix(unit_end);
        if (dot != std::string_view::npos) {
            if (!body.empty()) {
                return Error{"only the last unit of duration " + quoted(text) +
                             " may have a fraction"};
            }
            const Result<double> fraction = parse_real("0" + std::string(number.substr(dot)));
            if (!fraction) {
                return Error{fraction.error()};
            }
            const std::int64_t extra = vm::stdlib::fraction_nanoseconds(
                *fraction * static_cast<double>(unit.nanoseconds), total);
            if (__builtin_add_overflow(total, extra, &total)) {
                return Error{"duration " + quoted(text) + " is too long for 64-bit nanoseconds"};
            }
        }
        previous_unit = unit_index;
        first = false;
    }
    if (first) {
        return Error{"duration " + quoted(text) + " has no value"};
    }
    return ast::Literal{ast::DurationLiteral{negative ? -total : total, type}};
}

// Splits `text` at `separator` into exactly `count` decimal fields.
template <std::size_t count>
std::optional<std::array<int, count>> split_fields(std::string_view text, char separator) {
    std::array<int, count> fields{};
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t end = i + 1 < count ? text.find(separator) : text.size();
        if (end == std::string_view::npos || end == 0) {
            return std::nullopt;
        }
        const auto [stop, error] = std::from_chars(text.data(), text.data() + end, fields[i]);
        if (error != std::errc{} || stop != text.data() + end) {
            return std::nullopt;
        }
        text.remove_prefix(std::min(end + 1, text.size()));
    }
    return fields;
}

// Nanoseconds since 1970-01-01 of a yyyy-mm-dd date.
Result<std::int64_t> date_nanoseconds(std::string_view text, std::string_view literal) {
    const auto fields = split_fields<3>(text, '-');
    if (!fields) {
        return Error{"malformed date in " + quoted(literal) + ": expected yyyy-mm-dd"};
    }
    const std::chrono::year_month_day date{std::chrono::year{(*fields)[0]},
                                           std::chrono::month{static_cast<unsigned>((*fields)[1])},
                                           std::chrono::day{static_cast<unsigned>((*fields)[2])}};
    if (!date.ok()) {
        return Error{"the date in " + quoted(literal) + " does not exist"};
    }
    const std::int64_t days = std::chrono::sys_days{date}.time_since_epoch().count();
    std::int64_t nanoseconds = 0;
    if (__builtin_mul_overflow(days, kNanosecondsPerDay, &nanoseconds)) {
        return Error{"the date in " + quoted(literal) + " is out of range"};
    }
    return nanoseconds;
}

// Nanoseconds since midnight of hh:mm:ss[.fraction].
Result<std::int64_t> time_of_day_nanoseconds(std::string_view text, std::string_view literal) {
    const std::size_t dot = text.find('.');
    const auto fields = split_fields<3>(text.substr(0, dot), ':');
    if (!fields) {
        return Error{"malformed time of day in " + quoted(literal) + ": expected hh:mm:ss"};
    }
    const auto [hours, minutes, seconds] = *fields;
    if (hours < 0 || hours > 23 || minutes < 0 || minutes > 59 || seconds < 0 || seconds > 59) {
        return Error{"the time of day in " + quoted(literal) + " does not exist"};
    }
    std::int64_t nanoseconds = ((hours * 60LL + minutes) * 60LL + seconds) * kNanosecondsPerSecond;
    if (dot != std::string_view::npos) {
        const Result<double> fraction = parse_real("0" + std::string(text.substr(dot)));
        if (!fraction) {
            return Error{fraction.error()};
        }
        nanoseconds += vm::stdlib::fraction_nanoseconds(
            *fraction * static_cast<double>(kNanosecondsPerSecond), nanoseconds);
    }
    return nanoseconds;
}

// IEC 61131-3 ed. 3, 6.3.5, table 9.
Result<ast::Literal> decode_date_time(LiteralForm form, std::string_view text) {
    const auto [type, body] = split_prefix(text);
    if (form == LiteralForm::Date) {
        const auto date = date_nanoseconds(body, text);
        return date ? Result<ast::Literal>(ast::DateTimeLiteral{*date, type}) : Error{date.error()};
    }
    if (form == LiteralForm::TimeOfDay) {
        const auto time = time_of_day_nanoseconds(body, text);
        return time ? Result<ast::Literal>(ast::DateTimeLiteral{*time, type}) : Error{time.error()};
    }
    // yyyy-mm-dd-hh:mm:ss: the date ends at the third '-'.
    std::size_t split = std::string_view::npos;
    for (int dashes = 0; dashes < 3; ++dashes) {
        split = body.find('-', split == std::string_view::npos ? 0 : split + 1);
        if (split == std::string_view::npos) {
            return Error{"malformed date and time " + quoted(text) +
                         ": expected yyyy-mm-dd-hh:mm:ss"};
        }
    }
    const auto date = date_nanoseconds(body.substr(0, split), text);
    if (!date) {
        return Error{date.error()};
    }
    const auto time = time_of_day_nanoseconds(body.substr(split + 1), text);
    if (!time) {
        return Error{time.error()};
    }
    return ast::Literal{ast::DateTimeLiteral{*date + *time, type}};
}

void append_utf16(std::u16string& out, char32_t code_point) {
    if (code_point < 0x10000) {
        out += static_cast<char16_t>(code_point);
    } else {
        code_point -= 0x10000;
        out += static_cast<char16_t>(0xD800 + (code_point >> 10));
        out += static_cast<char16_t>(0xDC00 + (code_point & 0x3FF));
    }
}

// IEC 61131-3 ed. 3, 6.3.3, tables 6 and 7: `$$ $' $" $L $N $P $R $T`, `$hh` in single-byte
// strings and `$hhhh` in double-byte strings.
Result<ast::Literal> decode_string(std::string_view text, bool wide) {
    std::string narrow;
    std::u16string wide_value;
    const auto append = [&](char32_t c) {
        if (wide) {
            append_utf16(wide_value, c);
        } else {
            narrow += static_cast<char>(c);
        }
    };
    const std::string_view body = text.substr(1, text.size() - 2);
    for (std::size_t i = 0; i < body.size();) {
        if (body[i] != '$') {
            if (!wide) {
                narrow += body[i++]; // bytes as written: UTF-8 stays UTF-8
                continue;
            }
            const std::optional<char32_t> c = utf8::decode(body, i);
            append_utf16(wide_value, c.value_or(U'\uFFFD'));
            continue;
        }
        if (i + 1 >= body.size()) {
            return Error{"'$' at the end of a string must be written '$$'"};
        }
        const char escape =
            static_cast<char>(std::toupper(static_cast<unsigned char>(body[i + 1])));
        static constexpr std::array<std::pair<char, char>, 8> kEscapes{{{'$', '$'},
                                                                        {'\'', '\''},
                                                                        {'"', '"'},
                                                                        {'L', '\n'},
                                                                        {'N', '\n'},
                                                                        {'P', '\f'},
                                                                        {'R', '\r'},
                                                                        {'T', '\t'}}};
        bool simple = false;
        for (const auto& [letter, value] : kEscapes) {
            if (escape == letter) {
                append(static_cast<unsigned char>(value));
                simple = true;
            }
        }
        if (simple) {
            i += 2;
            continue;
        }
        const std::size_t hex_digits = wide ? 4 : 2;
        const std::string_view hex = body.substr(i + 1, hex_digits);
        const bool all_hex =
            hex.size() == hex_digits && std::all_of(hex.begin(), hex.end(), [](char c) {
                return std::isxdigit(static_cast<unsigned char>(c)) != 0;
            });
        if (!all_hex) {
            const std::size_t shown =
                std::isxdigit(static_cast<unsigned char>(body[i + 1])) ? hex.size() + 1 : 2;
            return Error{"invalid escape " + quoted(body.substr(i, shown)) +
                         " in string; use $$, $', $\", $L, $N, $P, $R, $T or $ followed by " +
                         std::to_string(hex_digits) + " hex digits"};
        }
        const Result<std::uint64_t> code = parse_digits(hex, 16);
        append(static_cast<char32_t>(*code));
        i += 1 + hex_digits;
    }
    if (const std::size_t length = wide ? wide_value.size() : narrow.size();
        length > vm::stdlib::kMaxStringCapacity) {
        return Error{"a string literal of " + std::to_string(length) +
                     " characters is longer than the longest string (" +
                     std::to_string(vm::stdlib::kMaxStringCapacity) + " characters)"};
    }
    if (wide) {
        return ast::Literal{ast::StringLiteral{std::move(wide_value), ElementaryType::Wstring}};
    }
    return ast::Literal{ast::StringLiteral{std::move(narrow), ElementaryType::String}};
}

std::string describe(bool negative, std::uint64_t magnitude) {
    return (negative && magnitude != 0 ? "-" : "") + std::to_string(magnitude);
}

Result<ast::Literal> typed_integer(ElementaryType type, bool negative, std::uint64_t magnitude) {
    const ast::IntegerRange range = *ast::integer_range(type);
    const std::uint64_t most_negative =
        range.min < 0 ? static_cast<std::uint64_t>(-(range.min + 1)) + 1 : 0;
    if (negative ? magnitude > most_negative : magnitude > range.max) {
        return Error{"value " + describe(negative, magnitude) + " is out of range for " +
                     std::string(ast::name_of(type)) + " (" + std::to_string(range.min) + ".." +
                     std::to_string(range.max) + ")"};
    }
    if (type == ElementaryType::Bool) {
        return ast::Literal{ast::BoolLiteral{magnitude == 1}};
    }
    return ast::Literal{ast::IntegerLiteral{magnitude, negative && magnitude != 0, type}};
}

bool is_name(std::string_view text) {
    if (text.empty() || std::isdigit(static_cast<unsigned char>(text.front()))) {
        return false;
    }
    for (char c : text) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') {
            return false;
        }
    }
    return true;
}

// `TYPE#value` (6.3.2 and 6.3.3) or a qualified enumeration value `Enum#Value` (6.4.4.2).
Result<ast::Literal> decode_typed(std::string_view text) {
    const std::size_t hash = text.find('#');
    const std::string_view prefix = text.substr(0, hash);
    std::string_view body = text.substr(hash + 1);
    const std::optional<ElementaryType> type = ast::elementary_type_from_name(prefix);
    if (!type) {
        if (!is_name(body)) {
            return Error{quoted(prefix) + " is not an elementary type, so " + quoted(text) +
                         " is not a typed literal"};
        }
        return ast::Literal{
            ast::EnumValueLiteral{{std::string(prefix), {}}, {std::string(body), {}}}};
    }
    const std::string type_name(ast::name_of(*type));
    if (*type == ElementaryType::String || *type == ElementaryType::Wstring ||
        *type == ElementaryType::Char || *type == ElementaryType::Wchar) {
        const bool wide = *type == ElementaryType::Wstring || *type == ElementaryType::Wchar;
        if (body.size() < 2 || body.front() != (wide ? '"' : '\'')) {
            return Error{type_name + "# needs a string in " + (wide ? "double" : "single") +
                         " quotes"};
        }
        Result<ast::Literal> decoded = decode_string(body, wide);
        if (!decoded) {
            return decoded;
        }
        auto& string = std::get<ast::StringLiteral>(*decoded);
        string.type = *type;
        const std::size_t length = wide ? std::get<std::u16string>(string.value).size()
                                        : std::get<std::string>(string.value).size();
        if ((*type == ElementaryType::Char || *type == ElementaryType::Wchar) && length != 1) {
            return Error{type_name + " literal " + quoted(text) +
                         " must hold exactly one character"};
        }
        return decoded;
    }
    if (*type == ElementaryType::Bool &&
        (equal_ignoring_case(body, "TRUE") || equal_ignoring_case(body, "FALSE"))) {
        return ast::Literal{ast::BoolLiteral{equal_ignoring_case(body, "TRUE")}};
    }
    const bool negative = !body.empty() && body.front() == '-';
    if (!body.empty() && (body.front() == '-' || body.front() == '+')) {
        body.remove_prefix(1);
    }
    // `1.5`, `1.5E3` or CODESYS's `1E3`; a based integer (`16#1E`) has no exponent.
    const bool real_syntax = body.find_first_of(".eE") != std::string_view::npos &&
                             body.find('#') == std::string_view::npos;
    if (ast::is_real(*type)) {
        Result<double> value = real_syntax ? parse_real(body) : Result<double>(0.0);
        if (!real_syntax) {
            const Result<std::uint64_t> integer = parse_integer(body);
            value =
                integer ? Result<double>(static_cast<double>(*integer)) : Error{integer.error()};
        }
        if (!value) {
            return Error{value.error()};
        }
        return ast::Literal{ast::RealLiteral{negative ? -*value : *value, *type}};
    }
    if (ast::integer_range(*type)) {
        if (real_syntax || body.empty() ||
            !std::isdigit(static_cast<unsigned char>(body.front()))) {
            return Error{type_name + "# needs an integer value, not " + quoted(body)};
        }
        const Result<std::uint64_t> magnitude = parse_integer(body);
        if (!magnitude) {
            return Error{magnitude.error()};
        }
        return typed_integer(*type, negative, *magnitude);
    }
    return Error{"malformed " + type_name + " literal " + quoted(text)};
}

} // namespace

core::Result<ast::Literal> decode_literal(LiteralForm form, std::string_view text) {
    switch (form) {
    case LiteralForm::Integer:
    case LiteralForm::BasedInteger: {
        const Result<std::uint64_t> value = parse_integer(text);
        if (!value) {
            return Error{value.error()};
        }
        return ast::Literal{ast::IntegerLiteral{*value, false, std::nullopt}};
    }
    case LiteralForm::Real: {
        const Result<double> value = parse_real(text);
        if (!value) {
            return Error{value.error()};
        }
        return ast::Literal{ast::RealLiteral{*value, std::nullopt}};
    }
    case LiteralForm::String:
        return decode_string(text, false);
    case LiteralForm::WideString:
        return decode_string(text, true);
    case LiteralForm::Duration:
        return decode_duration(text);
    case LiteralForm::Date:
    case LiteralForm::TimeOfDay:
    case LiteralForm::DateAndTime:
        return decode_date_time(form, text);
    case LiteralForm::Typed:
        return decode_typed(text);
    }
    return Error{"unknown literal form"};
}

} // namespace eposp::compiler
