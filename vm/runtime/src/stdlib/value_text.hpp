#pragma once

// The text forms of elementary values for *_TO_STRING and STRING_TO_*: what CODESYS prints, and
// what it reads back (IEC 61131-3 literal syntax, 6.3). Formatting writes into a fixed buffer,
// so conversions never allocate.

#include <array>
#include <cstdint>
#include <string_view>

namespace eposp::vm::stdlib {

/// Enough for any value's text: the longest is an LTIME of 292 years in every unit.
class ValueText {
public:
    void append(std::string_view text);
    void append_number(std::uint64_t value, int min_digits = 1);
    std::string_view view() const { return {chars_.data(), size_}; }

private:
    std::array<char, 64> chars_{};
    std::size_t size_ = 0;
};

void format_signed(ValueText& out, std::int64_t value);
void format_unsigned(ValueText& out, std::uint64_t value);
/// Shortest text that reads back to the same value: 1.5, 1, 0.1, 1E+20, -INF, NAN.
void format_real(ValueText& out, double value, bool single_precision);
/// T#1d2h3m4s5ms6us7ns with the zero units left out; T#0ms for zero; `prefix` is T# or LTIME#.
void format_duration(ValueText& out, std::int64_t ns, std::string_view prefix);
void format_date(ValueText& out, std::int64_t ns);          ///< D#2024-01-31
void format_time_of_day(ValueText& out, std::int64_t ns);   ///< TOD#12:34:56.789
void format_date_and_time(ValueText& out, std::int64_t ns); ///< DT#2024-01-31-12:34:56.789

// Parsing takes leading blanks, then as much of the form as is there; text that does not start
// with a valid form gives 0 (CODESYS does not signal errors from STRING_TO_*).
std::int64_t parse_integer(std::string_view text); ///< [+-]digits, 2#, 8#, 16#, underscores
double parse_real(std::string_view text);
bool parse_bool(std::string_view text);                  ///< TRUE (any case) or a non-zero number
std::int64_t parse_duration(std::string_view text);      ///< [T#|TIME#|LTIME#][-]1d2h3m4.5s6ms...
std::int64_t parse_date(std::string_view text);          ///< [D#|DATE#]YYYY-MM-DD
std::int64_t parse_time_of_day(std::string_view text);   ///< [TOD#|TIME_OF_DAY#]hh:mm:ss[.f]
std::int64_t parse_date_and_time(std::string_view text); ///< [DT#|DATE_AND_TIME#]date-tod

} // namespace eposp::vm::stdlib
