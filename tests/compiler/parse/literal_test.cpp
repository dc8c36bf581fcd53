// Every literal form of IEC 61131-3 ed. 3, 6.3 (tables 5 to 9), decoded to its exact value, and
// the malformed ones rejected with a message about the literal.
#include "eposp/compiler/parser.hpp"
#include "parse_helpers.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler {
namespace {

using test::expression_sexpr;
using test::statement_error;

struct LiteralCase {
    const char* name;
    const char* source;
    const char* expected;
};

void PrintTo(const LiteralCase& c, std::ostream* out) {
    *out << c.source;
}

class LiteralValue : public testing::TestWithParam<LiteralCase> {};

TEST_P(LiteralValue, DecodesExactly) {
    EXPECT_EQ(expression_sexpr(GetParam().source), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Iec, LiteralValue,
    testing::Values(
        LiteralCase{"Decimal", "42", "(int 42)"},
        LiteralCase{"Underscores", "1_000_000", "(int 1000000)"},
        LiteralCase{"Negative", "-5", "(int -5)"},
        LiteralCase{"Binary", "2#1010_1010", "(int 170)"},
        LiteralCase{"Octal", "8#777", "(int 511)"}, LiteralCase{"Hex", "16#FF", "(int 255)"},
        LiteralCase{"HexLowerCase", "16#ff", "(int 255)"},
        LiteralCase{"LargestUlint", "18446744073709551615", "(int 18446744073709551615)"},
        LiteralCase{"SmallestLint", "-9223372036854775808", "(int -9223372036854775808)"},
        LiteralCase{"TypedHex", "INT#16#FF", "(int 255 INT)"},
        LiteralCase{"TypedSmallestInt", "INT#-32768", "(int -32768 INT)"},
        LiteralCase{"TypedLargestUdint", "UDINT#4294967295", "(int 4294967295 UDINT)"},
        LiteralCase{"TypedByteBinary", "byte#2#1111_0000", "(int 240 BYTE)"},
        LiteralCase{"True", "TRUE", "(bool TRUE)"},
        LiteralCase{"FalseLowerCase", "false", "(bool FALSE)"},
        LiteralCase{"TypedBoolOne", "BOOL#1", "(bool TRUE)"},
        LiteralCase{"TypedBoolFalse", "BOOL#FALSE", "(bool FALSE)"},
        LiteralCase{"Real", "3.25", "(real 3.25)"},
        LiteralCase{"RealExponent", "1.5E3", "(real 1500)"},
        LiteralCase{"RealNegativeExponent", "1.0e-2", "(real 0.01)"},
        LiteralCase{"RealUnderscores", "1_000.5", "(real 1000.5)"},
        LiteralCase{"NegativeReal", "-0.5", "(real -0.5)"},
        LiteralCase{"TypedReal", "REAL#1.5", "(real 1.5 REAL)"},
        LiteralCase{"TypedLrealFromInteger", "LREAL#-2", "(real -2 LREAL)"},
        LiteralCase{"Duration", "T#1h2m3s4ms", "(TIME 3723004000000ns)"},
        LiteralCase{"DurationLongPrefix", "TIME#-5s", "(TIME -5000000000ns)"},
        LiteralCase{"DurationFraction", "t#1.5s", "(TIME 1500000000ns)"},
        LiteralCase{"DurationUnderscore", "T#1h_30m", "(TIME 5400000000000ns)"},
        LiteralCase{"DurationMostSignificantOverflows", "T#25h", "(TIME 90000000000000ns)"},
        LiteralCase{"DurationMicroseconds", "T#1ms2us", "(TIME 1002000ns)"},
        LiteralCase{"LongDuration", "LT#1d", "(LTIME 86400000000000ns)"},
        LiteralCase{"LongDurationNanoseconds", "LTIME#5ns", "(LTIME 5ns)"},
        LiteralCase{"Date", "D#2024-01-31", "(DATE 1706659200000000000ns)"},
        LiteralCase{"DateEpoch", "DATE#1970-01-01", "(DATE 0ns)"},
        LiteralCase{"LongDate", "LDATE#1970-01-02", "(LDATE 86400000000000ns)"},
        LiteralCase{"TimeOfDay", "TOD#12:30:15.5", "(TIME_OF_DAY 45015500000000ns)"},
        LiteralCase{"TimeOfDayLongPrefix", "TIME_OF_DAY#00:00:01", "(TIME_OF_DAY 1000000000ns)"},
        LiteralCase{"LongTimeOfDay", "LTOD#00:00:00.000000001", "(LTIME_OF_DAY 1ns)"},
        LiteralCase{"DateAndTime", "DT#1970-01-02-00:00:01", "(DATE_AND_TIME 86401000000000ns)"},
        LiteralCase{"DateAndTimeLongPrefix", "DATE_AND_TIME#1970-01-01-01:00:00",
                    "(DATE_AND_TIME 3600000000000ns)"},
        LiteralCase{"LongDateAndTime", "LDT#1970-01-01-00:00:00.5", "(LDATE_AND_TIME 500000000ns)"},
        LiteralCase{"String", "'abc'", "(STRING \"abc\")"},
        LiteralCase{"StringDollar", "'$$5'", "(STRING \"$5\")"},
        LiteralCase{"StringQuote", "'it$'s'", "(STRING \"it's\")"},
        LiteralCase{"StringHexByte", "'$41$42'", "(STRING \"AB\")"},
        LiteralCase{"TypedString", "STRING#'x'", "(STRING \"x\")"},
        LiteralCase{"Char", "CHAR#'A'", "(CHAR \"A\")"},
        LiteralCase{"WideString", "\"ab\"", "(WSTRING 2 units)"},
        LiteralCase{"WideChar", "WCHAR#\"$00E9\"", "(WCHAR 1 units)"},
        LiteralCase{"QualifiedEnumValue", "Color#Red", "(enum Color Red)"},
        LiteralCase{"Null", "NULL", "(null)"}),
    [](const auto& c) { return std::string(c.param.name); });

TEST(Literal, StringEscapesDecodeToControlCharacters) {
    const test::Parsed parsed =
        test::parse_text("PROGRAM P\ns := 'a$Nb$L$R$T$P$0A$n';\nEND_PROGRAM\n");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const auto& assignment =
        std::get<ast::AssignmentStatement>(parsed.unit.pous.front().body.front().node);
    const auto& literal = std::get<ast::LiteralExpression>(assignment.value->node);
    const auto& string = std::get<ast::StringLiteral>(literal.value);
    EXPECT_EQ(std::get<std::string>(string.value), "a\nb\n\r\t\f\n\n");
}

TEST(Literal, WideStringEscapesDecodeToUtf16) {
    const test::Parsed parsed = test::parse_text("PROGRAM P\ns := \"$0041$\"é€\";\nEND_PROGRAM\n");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const auto& assignment =
        std::get<ast::AssignmentStatement>(parsed.unit.pous.front().body.front().node);
    const auto& literal = std::get<ast::LiteralExpression>(assignment.value->node);
    const auto& string = std::get<ast::StringLiteral>(literal.value);
    EXPECT_EQ(std::get<std::u16string>(string.value), u"A\"é€");
}

struct MalformedCase {
    const char* name;
    const char* source;
    const char* message;
};

void PrintTo(const MalformedCase& c, std::ostream* out) {
    *out << c.source;
}

class MalformedLiteral : public testing::TestWithParam<MalformedCase> {};

TEST_P(MalformedLiteral, IsReportedWithAReason) {
    EXPECT_THAT(statement_error(std::string("x := ") + GetParam().source + ";"),
                testing::HasSubstr(GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    Iec, MalformedLiteral,
    testing::Values(
        MalformedCase{"BinaryDigitTwo", "2#102", "'2' is not a digit in base 2"},
        MalformedCase{"HexDigitG", "16#FG", "'G' is not a digit in base 16"},
        MalformedCase{"UnsupportedBase", "3#12", "base 3 is not supported; use 2#, 8# or 16#"},
        MalformedCase{"DoubleUnderscore", "1__0", "misplaced '_'"},
        MalformedCase{"TrailingUnderscore", "16#FF_", "misplaced '_'"},
        MalformedCase{"TooLarge", "99999999999999999999", "does not fit in 64 bits"},
        MalformedCase{"IntOutOfRange", "INT#40000",
                      "value 40000 is out of range for INT (-32768..32767)"},
        MalformedCase{"UnsignedNegative", "USINT#-1",
                      "value -1 is out of range for USINT (0..255)"},
        MalformedCase{"BoolTwo", "BOOL#2", "out of range for BOOL"},
        MalformedCase{"IntegerTypeWithReal", "SINT#1.5", "SINT# needs an integer value"},
        MalformedCase{"RealOutOfRange", "1.0E999", "out of the range of LREAL"},
        MalformedCase{"UnknownDurationUnit", "T#1x", "unknown unit 'x'"},
        MalformedCase{"DurationUnitsOutOfOrder", "T#1s1h", "must go from days down to nanoseconds"},
        MalformedCase{"DurationMinutesOverflow", "T#1h61m", "exceeds 59m"},
        MalformedCase{"DurationFractionNotLast", "T#1.5h2m", "only the last unit"},
        MalformedCase{"DurationWithoutUnit", "T#5", "expected a number followed by d, h, m, s"},
        MalformedCase{"NoLeapDay", "D#2023-02-29", "does not exist"},
        MalformedCase{"MonthThirteen", "D#2024-13-01", "does not exist"},
        MalformedCase{"MalformedDate", "D#2024-01", "expected yyyy-mm-dd"},
        MalformedCase{"Hour24", "TOD#24:00:00", "does not exist"},
        MalformedCase{"DateAndTimeWithoutTime", "DT#2024-01-01", "expected yyyy-mm-dd-hh:mm:ss"},
        MalformedCase{"UnknownEscape", "'a$Qb'", "invalid escape '$Q'"},
        MalformedCase{"ShortHexEscape", "'$4'", "invalid escape"},
        MalformedCase{"UnterminatedString", "'abc", "missing closing ' at the end of this string"},
        MalformedCase{"CharOfTwo", "CHAR#'ab'", "must hold exactly one character"},
        MalformedCase{"WideStringInSingleQuotes", "WSTRING#'x'", "needs a string in double quotes"},
        MalformedCase{"UnknownTypePrefix", "Foo#12", "'Foo' is not an elementary type"}),
    [](const auto& c) { return std::string(c.param.name); });

TEST(Literal, ErrorPointsAtTheLiteral) {
    const test::Parsed parsed = test::parse_text("PROGRAM P\nx := y + INT#70000;\nEND_PROGRAM\n");
    ASSERT_EQ(parsed.diagnostics.all().size(), 1u);
    const Diagnostic& error = parsed.diagnostics.all().front();
    EXPECT_EQ(error.range.begin, (SourcePosition{2, 10}));
    EXPECT_EQ(error.range.end, (SourcePosition{2, 18}));
}

} // namespace
} // namespace eposp::compiler
