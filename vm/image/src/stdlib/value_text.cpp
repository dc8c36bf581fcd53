#include "eposp/vm/stdlib/value_text.hpp"

#include "eposp/vm/stdlib/duration_fraction.hpp"
#include "eposp/vm/stdlib/time_units.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>

namespace eposp::vm::stdlib {
namespace {

char lower(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

/// Reads a literal from left to right; every accept* consumes only on success.
class Cursor {
public:
    explicit Cursor(std::string_view text) : text_(text) {
        while (!text_.empty() && (text_.front() == ' ' || text_.front() == '\t')) {
            text_.remove_prefix(1);
        }
    }

    bool accept(char c) {
        if (!text_.empty() && lower(text_.front()) == lower(c)) {
            text_.remove_prefix(1);
            return true;
        }
        return false;
    }
    /// Case-insensitive keyword such as `T#` or `ms`.
    bool accept(std::string_view word) {
        if (text_.size() < word.size()) {
            return false;
        }
        for (std::size_t i = 0; i < word.size(); ++i) {
            if (lower(text_[i]) != lower(word[i])) {
                return false;
            }
        }
        text_.remove_prefix(word.size());
        return true;
    }
    /// Digits in `base` with single underscores between them, wrapping modulo 2^64.
    std::optional<std::uint64_t> digits(unsigned base = 10, std::size_t* count = nullptr) {
        std::optional<std::uint64_t> value;
        std::size_t n = 0;
        while (!text_.empty()) {
            const auto digit = digit_value(text_.front());
            if (digit < base) {
                value = value.value_or(0) * base + digit;
                ++n;
            } else if (!(text_.front() == '_' && value)) {
                break;
            }
            text_.remove_prefix(1);
        }
        if (count != nullptr) {
            *count = n;
        }
        return value;
    }
    std::string_view rest() const { return text_; }

private:
    static unsigned digit_value(char c) {
        if (c >= '0' && c <= '9') {
            return static_cast<unsigned>(c - '0');
        }
        const char l = lower(c);
        return (l >= 'a' && l <= 'f') ? static_cast<unsigned>(l - 'a' + 10) : 99U;
    }

    std::string_view text_;
};

bool accept_any(Cursor& cursor, std::initializer_list<std::string_view> prefixes) {
    return std::any_of(prefixes.begin(), prefixes.end(),
                       [&](std::string_view p) { return cursor.accept(p); });
}

std::int64_t days_from_civil(int year, unsigned month, unsigned day, bool& valid) {
    using namespace std::chrono;
    const year_month_day date{std::chrono::year{year}, std::chrono::month{month},
                              std::chrono::day{day}};
    valid = date.ok();
    return valid ? sys_days{date}.time_since_epoch().count() : 0;
}

/// YYYY-MM-DD as days since 1970-01-01.
std::optional<std::int64_t> read_date(Cursor& c) {
    const auto year = c.digits();
    if (!year || !c.accept('-')) {
        return std::nullopt;
    }
    const auto month = c.digits();
    if (!month || !c.accept('-')) {
        return std::nullopt;
    }
    const auto day = c.digits();
    if (!day || *year > 9999 || *month > 12 || *day > 31) {
        return std::nullopt;
    }
    bool valid = false;
    const auto days = days_from_civil(static_cast<int>(*year), static_cast<unsigned>(*month),
                                      static_cast<unsigned>(*day), valid);
    return valid ? std::optional(days) : std::nullopt;
}

/// `.ddd`: the fraction of `unit` nanoseconds it stands for, after `before` nanoseconds
/// (duration_fraction.hpp: ties to even on the whole value).
std::int64_t read_fraction(Cursor& c, std::int64_t unit, std::int64_t before) {
    if (!c.accept('.')) {
        return 0;
    }
    std::size_t count = 0;
    const auto digits = c.digits(10, &count);
    if (!digits || count > 18) {
        return 0;
    }
    return fraction_nanoseconds(static_cast<double>(*digits) /
                                    std::pow(10.0, static_cast<double>(count)) *
                                    static_cast<double>(unit),
                                before);
}

/// hh:mm:ss[.f] as nanoseconds since midnight.
std::optional<std::int64_t> read_time_of_day(Cursor& c) {
    const auto hours = c.digits();
    if (!hours || *hours > 23 || !c.accept(':')) {
        return std::nullopt;
    }
    const auto minutes = c.digits();
    if (!minutes || *minutes > 59 || !c.accept(':')) {
        return std::nullopt;
    }
    const auto seconds = c.digits();
    if (!seconds || *seconds > 59) {
        return std::nullopt;
    }
    const std::int64_t whole = static_cast<std::int64_t>(*hours) * kNsPerH +
                               static_cast<std::int64_t>(*minutes) * kNsPerMin +
                               static_cast<std::int64_t>(*seconds) * kNsPerS;
    return whole + read_fraction(c, kNsPerS, whole);
}

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    const auto q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

void append_two(ValueText& out, std::int64_t value) {
    out.append_number(static_cast<std::uint64_t>(value), 2);
}

void append_civil_date(ValueText& out, std::int64_t days) {
    using namespace std::chrono;
    const year_month_day date{sys_days{std::chrono::days{days}}};
    const int year = static_cast<int>(date.year());
    if (year < 0) {
        out.append("-");
    }
    out.append_number(static_cast<std::uint64_t>(std::abs(year)), 4);
    out.append("-");
    append_two(out, static_cast<unsigned>(date.month()));
    out.append("-");
    append_two(out, static_cast<unsigned>(date.day()));
}

void append_clock(ValueText& out, std::int64_t ns_of_day) {
    append_two(out, ns_of_day / kNsPerH);
    out.append(":");
    append_two(out, ns_of_day / kNsPerMin % 60);
    out.append(":");
    append_two(out, ns_of_day / kNsPerS % 60);
    auto fraction = static_cast<std::uint64_t>(ns_of_day % kNsPerS);
    if (fraction != 0) {
        int digits = 9;
        while (fraction % 10 == 0) {
            fraction /= 10;
            --digits;
        }
        out.append(".");
        out.append_number(fraction, digits);
    }
}

} // namespace

void ValueText::append(std::string_view text) {
    const auto count = std::min(text.size(), chars_.size() - size_);
    if (count != 0) { // an empty view may have no data() at all
        std::memcpy(chars_.data() + size_, text.data(), count);
    }
    size_ += count;
}

void ValueText::append_number(std::uint64_t value, int min_digits) {
    std::array<char, 24> digits{};
    const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), value).ptr;
    const auto length = static_cast<int>(end - digits.data());
    for (int i = length; i < min_digits; ++i) {
        append("0");
    }
    append({digits.data(), static_cast<std::size_t>(length)});
}

void format_signed(ValueText& out, std::int64_t value) {
    if (value < 0) {
        out.append("-");
    }
    // Negating in unsigned arithmetic keeps LINT's minimum exact.
    const auto magnitude = static_cast<std::uint64_t>(value);
    out.append_number(value < 0 ? ~magnitude + 1 : magnitude);
}

void format_unsigned(ValueText& out, std::uint64_t value) {
    out.append_number(value);
}

void format_real(ValueText& out, double value, bool single_precision) {
    if (std::isnan(value)) {
        out.append("NAN");
        return;
    }
    if (std::isinf(value)) {
        out.append(value < 0 ? "-INF" : "INF");
        return;
    }
    std::array<char, 40> chars{};
    const auto end =
        single_precision
            ? std::to_chars(chars.data(), chars.data() + chars.size(), static_cast<float>(value))
                  .ptr
            : std::to_chars(chars.data(), chars.data() + chars.size(), value).ptr;
    std::transform(chars.data(), end, chars.data(), [](char c) { return c == 'e' ? 'E' : c; });
    out.append({chars.data(), static_cast<std::size_t>(end - chars.data())});
}

void format_duration(ValueText& out, std::int64_t ns, std::string_view prefix) {
    struct Unit {
        std::int64_t ns;
        std::string_view name;
    };
    static constexpr Unit kUnits[] = {{kNsPerDay, "d"}, {kNsPerH, "h"},   {kNsPerMin, "m"},
                                      {kNsPerS, "s"},   {kNsPerMs, "ms"}, {kNsPerUs, "us"},
                                      {1, "ns"}};
    out.append(prefix);
    if (ns == 0) {
        out.append("0ms");
        return;
    }
    if (ns < 0) {
        out.append("-");
    }
    auto rest = ns < 0 ? ~static_cast<std::uint64_t>(ns) + 1 : static_cast<std::uint64_t>(ns);
    for (const auto& unit : kUnits) {
        const auto size = static_cast<std::uint64_t>(unit.ns);
        if (rest >= size) {
            out.append_number(rest / size);
            out.append(unit.name);
            rest %= size;
        }
    }
}

void format_date(ValueText& out, std::int64_t ns, std::string_view prefix) {
    out.append(prefix);
    append_civil_date(out, floor_div(ns, kNsPerDay));
}

void format_time_of_day(ValueText& out, std::int64_t ns, std::string_view prefix) {
    out.append(prefix);
    append_clock(out, ns - floor_div(ns, kNsPerDay) * kNsPerDay);
}

void format_date_and_time(ValueText& out, std::int64_t ns, std::string_view prefix) {
    const auto days = floor_div(ns, kNsPerDay);
    out.append(prefix);
    append_civil_date(out, days);
    out.append("-");
    append_clock(out, ns - days * kNsPerDay);
}

std::int64_t parse_integer(std::string_view text) {
    Cursor c(text);
    const bool negative = c.accept('-');
    if (!negative) {
        c.accept('+');
    }
    auto value = c.digits();
    if (value && (*value == 2 || *value == 8 || *value == 16) && c.accept('#')) {
        value = c.digits(static_cast<unsigned>(*value));
    }
    const auto magnitude = value.value_or(0);
    return static_cast<std::int64_t>(negative ? ~magnitude + 1 : magnitude);
}

double parse_real(std::string_view text) {
    Cursor c(text);
    c.accept('+');
    const auto rest = c.rest();
    double value = 0.0;
    const auto [_, error] = std::from_chars(rest.data(), rest.data() + rest.size(), value);
    return error == std::errc{} ? value : 0.0;
}

bool parse_bool(std::string_view text) {
    Cursor c(text);
    return c.accept("TRUE") || parse_integer(text) != 0;
}

std::int64_t parse_duration(std::string_view text) {
    struct Unit {
        std::string_view name;
        std::int64_t ns;
    };
    // Two-letter units first, so that `ms` is not read as minutes.
    static constexpr Unit kUnits[] = {{"ms", kNsPerMs}, {"us", kNsPerUs}, {"ns", 1},
                                      {"d", kNsPerDay}, {"h", kNsPerH},   {"m", kNsPerMin},
                                      {"s", kNsPerS}};
    Cursor c(text);
    accept_any(c, {"LTIME#", "TIME#", "LT#", "T#"});
    const bool negative = c.accept('-');
    std::uint64_t total = 0;
    while (const auto whole = c.digits()) {
        bool has_unit = false;
        for (const auto& unit : kUnits) {
            Cursor after = c;
            const std::uint64_t so_far = total + *whole * static_cast<std::uint64_t>(unit.ns);
            const auto fraction = read_fraction(after, unit.ns, static_cast<std::int64_t>(so_far));
            if (after.accept(unit.name)) {
                total = so_far + static_cast<std::uint64_t>(fraction);
                c = after;
                has_unit = true;
                break;
            }
        }
        if (!has_unit) {
            break;
        }
        c.accept('_');
    }
    return static_cast<std::int64_t>(negative ? ~total + 1 : total);
}

/// `days` since 1970 plus `ns_of_day`, if a 64-bit nanosecond count holds it (1677..2262).
std::optional<std::int64_t> to_ns(std::int64_t days, std::int64_t ns_of_day) {
    std::int64_t ns = 0;
    if (__builtin_mul_overflow(days, kNsPerDay, &ns) ||
        __builtin_add_overflow(ns, ns_of_day, &ns)) {
        return std::nullopt;
    }
    return ns;
}

std::int64_t parse_date(std::string_view text) {
    Cursor c(text);
    accept_any(c, {"LDATE#", "LD#", "DATE#", "D#"});
    const auto days = read_date(c);
    return days ? to_ns(*days, 0).value_or(0) : 0;
}

std::int64_t parse_time_of_day(std::string_view text) {
    Cursor c(text);
    accept_any(c, {"LTIME_OF_DAY#", "LTOD#", "TIME_OF_DAY#", "TOD#"});
    return read_time_of_day(c).value_or(0);
}

std::int64_t parse_date_and_time(std::string_view text) {
    Cursor c(text);
    accept_any(c, {"LDATE_AND_TIME#", "LDT#", "DATE_AND_TIME#", "DT#"});
    const auto days = read_date(c);
    if (!days || !c.accept('-')) {
        return 0;
    }
    const auto time = read_time_of_day(c);
    return time ? to_ns(*days, *time).value_or(0) : 0;
}

std::optional<TextForm> text_form(NativeType type) {
    for (const TypeTextForm& entry : kTextForms) {
        if (entry.type == type) {
            return entry.form;
        }
    }
    return std::nullopt;
}

void format_value(ValueText& out, TextForm form, std::int64_t value) {
    switch (form) {
    case TextForm::Bool:
        out.append(value != 0 ? "TRUE" : "FALSE");
        return;
    case TextForm::Signed:
        return format_signed(out, value);
    case TextForm::Unsigned:
        return format_unsigned(out, static_cast<std::uint64_t>(value));
    case TextForm::Real: // format_real's
        return;
    case TextForm::Time:
        return format_duration(out, value, "T#");
    case TextForm::LongTime:
        return format_duration(out, value, "LTIME#");
    case TextForm::Date:
        return format_date(out, value, "D#");
    case TextForm::LongDate:
        return format_date(out, value, "LDATE#");
    case TextForm::TimeOfDay:
        return format_time_of_day(out, value, "TOD#");
    case TextForm::LongTimeOfDay:
        return format_time_of_day(out, value, "LTOD#");
    case TextForm::DateAndTime:
        return format_date_and_time(out, value, "DT#");
    case TextForm::LongDateAndTime:
        return format_date_and_time(out, value, "LDT#");
    }
}

std::int64_t parse_value(std::string_view text, TextForm form) {
    switch (form) {
    case TextForm::Bool:
        return parse_bool(text) ? 1 : 0;
    case TextForm::Time:
    case TextForm::LongTime:
        return parse_duration(text);
    case TextForm::Date:
    case TextForm::LongDate:
        return parse_date(text);
    case TextForm::TimeOfDay:
    case TextForm::LongTimeOfDay:
        return parse_time_of_day(text);
    case TextForm::DateAndTime:
    case TextForm::LongDateAndTime:
        return parse_date_and_time(text);
    default:
        return parse_integer(text);
    }
}

} // namespace eposp::vm::stdlib
