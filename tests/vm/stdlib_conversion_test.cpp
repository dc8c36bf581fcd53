// <TYPE>_TO_STRING and STRING_TO_<TYPE> for every elementary type (IEC 61131-3 tables 22-27),
// through CallNative: the text CODESYS prints, the literal forms it reads back, and garbage.

#include "stdlib_harness.hpp"

#include <cmath>
#include <limits>

namespace eposp::vm::test {
namespace {

constexpr std::int64_t kMs = 1'000'000;
constexpr std::int64_t kS = 1'000 * kMs;
constexpr std::int64_t kDay = 86'400 * kS;
constexpr std::int64_t kDate20240131 = 19'753 * kDay;
constexpr std::int64_t kTod123456789 = (12 * 3600 + 34 * 60 + 56) * kS + 789 * kMs;

struct ToStringCase {
    const char* function;
    NativeArg value;
    std::string expected;
};

void PrintTo(const ToStringCase& c, std::ostream* os) {
    *os << c.function << " -> " << c.expected;
}

class ToString : public ::testing::TestWithParam<ToStringCase> {};

TEST_P(ToString, PrintsTheIecText) {
    const auto& c = GetParam();
    StdlibCall call;
    const auto destination = call.string(80, "old");
    ASSERT_EQ(call.call(c.function, {StdlibCall::string_arg(destination), c.value}),
              RunState::Finished);
    EXPECT_EQ(call.text(destination), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Integers, ToString,
    ::testing::Values(
        ToStringCase{"BOOL_TO_STRING", value(std::uint8_t{1}), "TRUE"},
        ToStringCase{"BOOL_TO_STRING", value(std::uint8_t{0}), "FALSE"},
        ToStringCase{"SINT_TO_STRING", value(std::int8_t{-128}), "-128"},
        ToStringCase{"INT_TO_STRING", value(std::int16_t{-1234}), "-1234"},
        ToStringCase{"DINT_TO_STRING", value(std::int32_t{2'147'483'647}), "2147483647"},
        ToStringCase{"LINT_TO_STRING", value(std::numeric_limits<std::int64_t>::min()),
                     "-9223372036854775808"},
        ToStringCase{"USINT_TO_STRING", value(std::uint8_t{255}), "255"},
        ToStringCase{"UINT_TO_STRING", value(std::uint16_t{65535}), "65535"},
        ToStringCase{"UDINT_TO_STRING", value(std::uint32_t{4'294'967'295}), "4294967295"},
        ToStringCase{"ULINT_TO_STRING", value(std::numeric_limits<std::uint64_t>::max()),
                     "18446744073709551615"},
        ToStringCase{"BYTE_TO_STRING", value(std::uint8_t{0xFF}), "255"},
        ToStringCase{"WORD_TO_STRING", value(std::uint16_t{0x1234}), "4660"},
        ToStringCase{"DWORD_TO_STRING", value(std::uint32_t{7}), "7"},
        ToStringCase{"LWORD_TO_STRING", value(std::uint64_t{0}), "0"}));

INSTANTIATE_TEST_SUITE_P(
    Reals, ToString,
    ::testing::Values(
        ToStringCase{"REAL_TO_STRING", value(1.5F), "1.5"},
        ToStringCase{"REAL_TO_STRING", value(1.0F), "1"},
        ToStringCase{"REAL_TO_STRING", value(0.1F), "0.1"},
        ToStringCase{"REAL_TO_STRING", value(-2.25F), "-2.25"},
        ToStringCase{"REAL_TO_STRING", value(1e20F), "1E+20"},
        ToStringCase{"LREAL_TO_STRING", value(3.141592653589793), "3.141592653589793"},
        ToStringCase{"LREAL_TO_STRING", value(1e-7), "1E-07"},
        ToStringCase{"LREAL_TO_STRING", value(-std::numeric_limits<double>::infinity()), "-INF"},
        ToStringCase{"LREAL_TO_STRING", value(std::numeric_limits<double>::quiet_NaN()), "NAN"}));

INSTANTIATE_TEST_SUITE_P(
    TimesAndDates, ToString,
    ::testing::Values(
        ToStringCase{"TIME_TO_STRING", value((3600 + 120 + 3) * kS + 4 * kMs), "T#1h2m3s4ms"},
        ToStringCase{"TIME_TO_STRING", value(std::int64_t{0}), "T#0ms"},
        ToStringCase{"TIME_TO_STRING", value(-1500 * kMs), "T#-1s500ms"},
        ToStringCase{"TIME_TO_STRING", value(kDay + 1), "T#1d1ns"},
        ToStringCase{"LTIME_TO_STRING", value(2 * kS + 3'000), "LTIME#2s3us"},
        ToStringCase{"DATE_TO_STRING", value(kDate20240131), "D#2024-01-31"},
        ToStringCase{"DATE_TO_STRING", value(-kDay), "D#1969-12-31"},
        ToStringCase{"TOD_TO_STRING", value(kTod123456789), "TOD#12:34:56.789"},
        ToStringCase{"TOD_TO_STRING", value(std::int64_t{0}), "TOD#00:00:00"},
        ToStringCase{"DT_TO_STRING", value(kDate20240131 + kTod123456789),
                     "DT#2024-01-31-12:34:56.789"},
        ToStringCase{"LDATE_TO_STRING", value(kDate20240131), "LDATE#2024-01-31"},
        ToStringCase{"LTIME_OF_DAY_TO_STRING", value(kTod123456789 + 1), "LTOD#12:34:56.789000001"},
        ToStringCase{"LDATE_AND_TIME_TO_STRING", value(kDate20240131 - 1),
                     "LDT#2024-01-30-23:59:59.999999999"}));

TEST(ToString, TextIsCutAtTheDestinationCapacity) {
    StdlibCall call;
    const auto destination = call.string(3);
    ASSERT_EQ(call.call("DINT_TO_STRING",
                        {StdlibCall::string_arg(destination), value(std::int32_t{-12345})}),
              RunState::Finished);
    EXPECT_EQ(call.text(destination), "-12");
}

struct FromStringCase {
    const char* function;
    const char* text;
    std::uint64_t expected; ///< the result's bits
};

void PrintTo(const FromStringCase& c, std::ostream* os) {
    *os << c.function << "('" << c.text << "')";
}

class FromString : public ::testing::TestWithParam<FromStringCase> {};

TEST_P(FromString, ReadsTheIecText) {
    const auto& c = GetParam();
    StdlibCall call;
    ASSERT_EQ(call.call(c.function, {call.string_arg(80, c.text)}), RunState::Finished);
    const auto size = scalar_size(call.harness.natives.find(c.function)->signature.result);
    std::uint64_t result = 0;
    std::memcpy(&result, call.harness.machine->memory().data() + call.harness.instance, size);
    EXPECT_EQ(result, c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Integers, FromString,
    ::testing::Values(
        FromStringCase{"STRING_TO_INT", "123", 123},
        FromStringCase{"STRING_TO_INT", "  -42", bits(std::int16_t{-42})},
        FromStringCase{"STRING_TO_INT", "+7", 7}, FromStringCase{"STRING_TO_INT", "12abc", 12},
        FromStringCase{"STRING_TO_INT", "abc", 0}, FromStringCase{"STRING_TO_INT", "", 0},
        FromStringCase{"STRING_TO_INT", "70000", bits(std::int16_t{4464})}, // wraps like INT
        FromStringCase{"STRING_TO_DINT", "1_000_000", 1'000'000},
        FromStringCase{"STRING_TO_DWORD", "16#FF_FF", 0xFFFF},
        FromStringCase{"STRING_TO_BYTE", "2#1010", 10},
        FromStringCase{"STRING_TO_USINT", "8#17", 15},
        FromStringCase{"STRING_TO_LINT", "-9223372036854775808", 0x8000000000000000},
        FromStringCase{"STRING_TO_ULINT", "18446744073709551615", 0xFFFFFFFFFFFFFFFF},
        FromStringCase{"STRING_TO_BOOL", "TRUE", 1}, FromStringCase{"STRING_TO_BOOL", "true", 1},
        FromStringCase{"STRING_TO_BOOL", "1", 1}, FromStringCase{"STRING_TO_BOOL", "FALSE", 0},
        FromStringCase{"STRING_TO_BOOL", "yes", 0}));

INSTANTIATE_TEST_SUITE_P(Reals, FromString,
                         ::testing::Values(FromStringCase{"STRING_TO_REAL", "1.5", bits(1.5F)},
                                           FromStringCase{"STRING_TO_REAL", "-2.5E3",
                                                          bits(-2500.0F)},
                                           FromStringCase{"STRING_TO_LREAL", " +0.25", bits(0.25)},
                                           FromStringCase{"STRING_TO_LREAL", "x1", bits(0.0)}));

INSTANTIATE_TEST_SUITE_P(
    TimesAndDates, FromString,
    ::testing::Values(
        FromStringCase{"STRING_TO_TIME", "T#1h2m3s4ms", bits((3600 + 120 + 3) * kS + 4 * kMs)},
        FromStringCase{"STRING_TO_TIME", "time#1.5s", bits(1500 * kMs)},
        FromStringCase{"STRING_TO_TIME", "T#-250ms", bits(-250 * kMs)},
        FromStringCase{"STRING_TO_TIME", "1d_2h", bits(kDay + 2 * 3600 * kS)},
        FromStringCase{"STRING_TO_TIME", "T#", 0},
        FromStringCase{"STRING_TO_LTIME", "LTIME#5us7ns", 5'007},
        FromStringCase{"STRING_TO_DATE", "D#2024-01-31", bits(kDate20240131)},
        FromStringCase{"STRING_TO_DATE", "DATE#2024-02-30", 0},
        FromStringCase{"STRING_TO_DATE", "D#9999-12-31", 0}, // past 2262: no 64-bit ns count
        FromStringCase{"STRING_TO_DT", "DT#2262-04-11-23:47:16.854775807", 0x7FFFFFFFFFFFFFFF},
        FromStringCase{"STRING_TO_DT", "DT#2262-04-11-23:47:16.854775808", 0},
        FromStringCase{"STRING_TO_TOD", "TOD#12:34:56.789", bits(kTod123456789)},
        FromStringCase{"STRING_TO_TOD", "TIME_OF_DAY#24:00:00", 0},
        FromStringCase{"STRING_TO_DT", "DT#2024-01-31-12:34:56.789",
                       bits(kDate20240131 + kTod123456789)},
        FromStringCase{"STRING_TO_DT", "DT#2024-01-31", 0},
        FromStringCase{"STRING_TO_LDATE", "LDATE#2024-01-31", bits(kDate20240131)},
        FromStringCase{"STRING_TO_LDATE", "LD#2024-01-31", bits(kDate20240131)},
        FromStringCase{"STRING_TO_DATE", "LDATE#2024-01-31", bits(kDate20240131)},
        FromStringCase{"STRING_TO_LTIME_OF_DAY", "LTOD#12:34:56.789", bits(kTod123456789)},
        FromStringCase{"STRING_TO_LTIME_OF_DAY", "LTIME_OF_DAY#00:00:00.000000001", 1},
        FromStringCase{"STRING_TO_LDATE_AND_TIME", "LDT#2024-01-31-12:34:56.789",
                       bits(kDate20240131 + kTod123456789)},
        FromStringCase{"STRING_TO_LDATE_AND_TIME", "LDATE_AND_TIME#1969-12-31-23:59:59.999999999",
                       bits(std::int64_t{-1})}));

TEST(FromString, EveryPrintedValueReadsBack) {
    const std::pair<const char*, std::int64_t> values[] = {
        {"TIME", -(kDay + 7 * kMs + 3)},
        {"DATE", kDate20240131},
        {"TOD", kTod123456789},
        {"DT", kDate20240131 + kTod123456789 + 1},
        {"LINT", -77},
        {"LDATE", -kDate20240131},
        {"LTIME_OF_DAY", kTod123456789 + 3},
        {"LDATE_AND_TIME", -(kDate20240131 + 11)},
    };
    for (const auto& [type, v] : values) {
        StdlibCall call;
        const auto text = call.string(80);
        call.emit_call(std::string(type) + "_TO_STRING", {StdlibCall::string_arg(text), value(v)});
        call.emit_call("STRING_TO_" + std::string(type), {StdlibCall::string_arg(text)});
        ASSERT_EQ(call.run(), RunState::Finished);
        EXPECT_EQ(call.result<std::int64_t>(), v) << type << " " << call.text(text);
    }
}

} // namespace
} // namespace eposp::vm::test
