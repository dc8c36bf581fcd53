#pragma once

// The text forms of elementary values for *_TO_STRING and STRING_TO_*: what CODESYS prints, and
// what it reads back (IEC 61131-3 literal syntax, 6.3). Formatting writes into a fixed buffer,
// so conversions never allocate. The VM's natives (string_conversions.cpp) and the compiler's
// constant folder both convert with these.

#include "eposp/vm/native_type.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace eposp::vm::stdlib {

/// How a value of an elementary type is written and read as text.
enum class TextForm : std::uint8_t {
    Bool,
    Signed,
    Unsigned,
    Real,
    Time,
    LongTime,
    Date,
    LongDate,
    TimeOfDay,
    LongTimeOfDay,
    DateAndTime,
    LongDateAndTime
};

struct TypeTextForm {
    NativeType type;
    TextForm form;
};

/// The types that convert to and from STRING (table 22), each with its form. BYTE..LWORD print
/// in decimal, as CODESYS's BYTE_TO_STRING does.
inline constexpr TypeTextForm kTextForms[] = {
    {NativeType::Bool, TextForm::Bool},           {NativeType::Sint, TextForm::Signed},
    {NativeType::Int, TextForm::Signed},          {NativeType::Dint, TextForm::Signed},
    {NativeType::Lint, TextForm::Signed},         {NativeType::Usint, TextForm::Unsigned},
    {NativeType::Uint, TextForm::Unsigned},       {NativeType::Udint, TextForm::Unsigned},
    {NativeType::Ulint, TextForm::Unsigned},      {NativeType::Byte, TextForm::Unsigned},
    {NativeType::Word, TextForm::Unsigned},       {NativeType::Dword, TextForm::Unsigned},
    {NativeType::Lword, TextForm::Unsigned},      {NativeType::Real, TextForm::Real},
    {NativeType::Lreal, TextForm::Real},          {NativeType::Time, TextForm::Time},
    {NativeType::Ltime, TextForm::LongTime},      {NativeType::Date, TextForm::Date},
    {NativeType::Ldate, TextForm::LongDate},      {NativeType::TimeOfDay, TextForm::TimeOfDay},
    {NativeType::Ltod, TextForm::LongTimeOfDay},  {NativeType::DateAndTime, TextForm::DateAndTime},
    {NativeType::Ldt, TextForm::LongDateAndTime},
};

/// The form of `type`; none for a type that has no conversion to STRING.
std::optional<TextForm> text_form(NativeType type);

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

/// <TYPE>_TO_STRING of a value of `form`, any but Real (format_real): a BOOL as 0 or 1, an
/// integer sign- or zero-extended to 64 bits as its type is signed or not, a time in ns.
void format_value(ValueText& out, TextForm form, std::int64_t value);
/// STRING_TO_<TYPE> of a `form` other than Real (parse_real): the value as 64 bits, which the
/// conversion then cuts to the type's width.
std::int64_t parse_value(std::string_view text, TextForm form);

void format_signed(ValueText& out, std::int64_t value);
void format_unsigned(ValueText& out, std::uint64_t value);
/// Shortest text that reads back to the same value: 1.5, 1, 0.1, 1E+20, -INF, NAN.
void format_real(ValueText& out, double value, bool single_precision);
/// T#1d2h3m4s5ms6us7ns with the zero units left out; T#0ms for zero; `prefix` is T# or LTIME#.
void format_duration(ValueText& out, std::int64_t ns, std::string_view prefix);
/// `prefix` 2024-01-31: D# or LDATE#.
void format_date(ValueText& out, std::int64_t ns, std::string_view prefix);
/// `prefix` 12:34:56.789, the fraction to the nanosecond without trailing zeros: TOD# or LTOD#.
void format_time_of_day(ValueText& out, std::int64_t ns, std::string_view prefix);
/// `prefix` 2024-01-31-12:34:56.789: DT# or LDT#.
void format_date_and_time(ValueText& out, std::int64_t ns, std::string_view prefix);

// Parsing takes leading blanks, then as much of the form as is there; text that does not start
// with a valid form gives 0 (CODESYS does not signal errors from STRING_TO_*).
std::int64_t parse_integer(std::string_view text); ///< [+-]digits, 2#, 8#, 16#, underscores
double parse_real(std::string_view text);
bool parse_bool(std::string_view text);             ///< TRUE (any case) or a non-zero number
std::int64_t parse_duration(std::string_view text); ///< [T#|TIME#|LTIME#][-]1d2h3m4.5s6ms...
std::int64_t parse_date(std::string_view text);     ///< [D#|DATE#|LD#|LDATE#]YYYY-MM-DD
/// [TOD#|TIME_OF_DAY#|LTOD#|LTIME_OF_DAY#]hh:mm:ss[.f]
std::int64_t parse_time_of_day(std::string_view text);
/// [DT#|DATE_AND_TIME#|LDT#|LDATE_AND_TIME#]date-tod
std::int64_t parse_date_and_time(std::string_view text);

} // namespace eposp::vm::stdlib
