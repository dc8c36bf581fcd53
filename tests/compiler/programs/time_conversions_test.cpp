// Conversions between the times and dates (table 22): a DATE or LDATE made of any other time is
// its day at midnight and a TOD or LTOD its time since midnight, as DT_TO_DATE and DT_TO_TOD
// take a DT apart, also before 1970 and at either width; the others keep the nanoseconds. Each
// value is compared, not printed: a TOD of more than a day would print as its time of day.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;
constexpr std::int64_t kHour = 3'600 * kSecond;
constexpr std::int64_t kDay = 24 * kHour;
constexpr std::int64_t kJanuary31 = 19'753 * kDay; // D#2024-01-31
constexpr std::int64_t kClock = 12 * kHour + 34 * 60 * kSecond + 56 * kSecond + 1;

struct Conversion {
    const char* type;       ///< the result's type
    const char* expression; ///< of the inputs below
    std::int64_t expected;  ///< the result in nanoseconds
};

const Conversion kConversions[] = {
    {"LTOD", "LDT_TO_LTOD(ldt)", kClock},
    {"LDATE", "LDT_TO_LDATE(ldt)", kJanuary31},
    {"TOD", "LDT_TO_TOD(ldt)", kClock},
    {"DATE", "LDT_TO_DATE(ldt)", kJanuary31},
    {"LTOD", "DT_TO_LTOD(dt)", kClock},
    {"LDATE", "DT_TO_LDATE(dt)", kJanuary31},
    {"TOD", "DT_TO_TOD(early)", 23 * kHour},
    {"DATE", "DT_TO_DATE(early)", -kDay},
    {"TOD", "DATE_TO_TOD(d)", 0},
    {"DATE", "TOD_TO_DATE(tod)", 0},
    {"TOD", "TIME_TO_TOD(t)", kHour},
    {"TOD", "TIME_TO_TOD(-t)", 23 * kHour},
    {"LTOD", "LTIME_TO_LTOD(lt)", kHour},
    {"DATE", "TIME_TO_DATE(t)", kDay},
    {"DT", "TOD_TO_DT(tod)", kClock},
    {"DT", "DATE_TO_DT(d)", kJanuary31},
    {"LDT", "DT_TO_LDT(dt)", kJanuary31 + kClock},
    {"DT", "LDT_TO_DT(ldt)", kJanuary31 + kClock},
    {"LTOD", "TOD_TO_LTOD(tod)", kClock},
    {"TIME", "TOD_TO_TIME(tod)", kClock},
};

constexpr const char* kInputs = R"(
    ldt : LDT := LDT#2024-01-31-12:34:56.000000001; dt : DT := DT#2024-01-31-12:34:56.000000001;
    early : DT := DT#1969-12-31-23:00:00; d : DATE := D#2024-01-31;
    tod : TOD := TOD#12:34:56.000000001; t : TIME := T#25h; lt : LTIME := LTIME#25h;
END_VAR
)";

/// Each conversion assigned in the body, or (`initial`) the initial value of its variable with
/// the inputs CONSTANTs, which the typing stage folds.
std::string program(bool initial) {
    std::string source =
        std::string("PROGRAM Main\n") + (initial ? "VAR CONSTANT" : "VAR") + kInputs + "VAR\n";
    std::string body;
    for (std::size_t i = 0; i < std::size(kConversions); ++i) {
        const Conversion& c = kConversions[i];
        const std::string name = "x" + std::to_string(i);
        source += "    " + name + " : " + c.type +
                  (initial ? std::string(" := ") + c.expression : std::string()) + ";\n";
        if (!initial) {
            body += name + " := " + c.expression + ";\n";
        }
    }
    return source + "END_VAR\n" + body + "END_PROGRAM\n";
}

void expect_the_conversions(bool initial) {
    StProgram run(program(initial));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    for (std::size_t i = 0; i < std::size(kConversions); ++i) {
        EXPECT_EQ(run.get<std::int64_t>("Main.x" + std::to_string(i)), kConversions[i].expected)
            << kConversions[i].expression;
    }
}

TEST(TimeConversions, ADateIsTheDayAndATimeOfDayTheTimeSinceMidnightOfAnyTime) {
    expect_the_conversions(false);
}

// The typing stage folds the same values: an initial value takes them.
TEST(TimeConversions, FoldedInitialValuesAreTheValuesComputedAtRunTime) {
    expect_the_conversions(true);
}

} // namespace
} // namespace eposp::compiler::test
