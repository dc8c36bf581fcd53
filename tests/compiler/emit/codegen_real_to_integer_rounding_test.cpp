// A REAL or LREAL becomes an integer by rounding to nearest with ties to even (IEC 61131-3 ed. 3
// 6.6.2.5.6, IEC 60559), into every integer and bit string type, from a variable, from a
// literal and through TO_<T>; a value outside the target's range saturates at its limit
// (docs/st-language.md). TRUNC stays truncation. Issue 16, defect 3.
#include "codegen_harness.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <string>

namespace eposp::compiler::test {
namespace {

struct Target {
    const char* name;
    int bytes;
    bool sign;
};

void PrintTo(const Target& target, std::ostream* out) {
    *out << target.name;
}

constexpr std::array kTargets{
    Target{"SINT", 1, true},   Target{"INT", 2, true},    Target{"DINT", 4, true},
    Target{"LINT", 8, true},   Target{"USINT", 1, false}, Target{"UINT", 2, false},
    Target{"UDINT", 4, false}, Target{"ULINT", 8, false}, Target{"BYTE", 1, false},
    Target{"WORD", 2, false},  Target{"DWORD", 4, false}, Target{"LWORD", 8, false},
};

/// The ties, each with its nearest even neighbour, and a value just off a tie.
struct Tie {
    const char* text;
    std::int64_t rounded;
};
constexpr std::array kTies{
    Tie{"2.5", 2}, Tie{"-0.5", 0}, Tie{"3.5", 4},   Tie{"1234566.5", 1234566}, Tie{"-2.5", -2},
    Tie{"0.5", 0}, Tie{"1.5", 2},  Tie{"-1.5", -2}, Tie{"2.500001", 3}};

/// `value` saturated into the target's range, as its reader sees it.
std::int64_t saturated(const Target& target, std::int64_t value) {
    if (target.bytes == 8) {
        return target.sign || value >= 0 ? value : 0;
    }
    const int bits = 8 * target.bytes;
    const std::int64_t low = target.sign ? -(std::int64_t{1} << (bits - 1)) : 0;
    const std::int64_t high =
        target.sign ? (std::int64_t{1} << (bits - 1)) - 1 : (std::int64_t{1} << bits) - 1;
    return std::clamp(value, low, high);
}

template <typename Signed, typename Unsigned>
std::int64_t read_as(const StProgram& run, bool sign, const std::string& path) {
    return sign ? std::int64_t{run.get<Signed>(path)}
                : static_cast<std::int64_t>(run.get<Unsigned>(path));
}

std::int64_t read(const StProgram& run, const Target& target, const std::string& path) {
    switch (target.bytes) {
    case 1:
        return read_as<std::int8_t, std::uint8_t>(run, target.sign, path);
    case 2:
        return read_as<std::int16_t, std::uint16_t>(run, target.sign, path);
    case 4:
        return read_as<std::int32_t, std::uint32_t>(run, target.sign, path);
    default:
        return run.get<std::int64_t>(path);
    }
}

class RealToInteger : public testing::TestWithParam<Target> {};

TEST_P(RealToInteger, RoundsTiesToEvenAndSaturates) {
    const Target& target = GetParam();
    const std::string t = target.name;
    std::string declarations;
    std::string body;
    for (std::size_t i = 0; i < kTies.size(); ++i) {
        const std::string n = std::to_string(i);
        const std::string v = kTies[i].text;
        declarations += "r" + n + " : REAL := " + v + "; l" + n + " : LREAL := " + v + "; a" + n +
                        ", b" + n + ", c" + n + ", d" + n + " : " + t + ";\n";
        body += "a" + n + " := REAL_TO_" + t + "(r" + n + "); b" + n + " := LREAL_TO_" + t + "(l" +
                n + "); c" + n + " := LREAL_TO_" + t + "(" + v + "); d" + n + " := TO_" + t + "(r" +
                n + ");\n";
    }
    StProgram run("PROGRAM Main\nVAR\n" + declarations + "END_VAR\n" + body + "END_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    for (std::size_t i = 0; i < kTies.size(); ++i) {
        const std::string n = std::to_string(i);
        const std::int64_t expected = saturated(target, kTies[i].rounded);
        for (const char* form : {"a", "b", "c", "d"}) {
            EXPECT_EQ(read(run, target, std::string("Main.") + form + n), expected)
                << form << ": " << t << " of " << kTies[i].text;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(EveryIntegerTarget, RealToInteger, testing::ValuesIn(kTargets),
                         [](const testing::TestParamInfo<Target>& target) {
                             return std::string(target.param.name);
                         });

TEST(RealToInteger, OutOfRangeSaturatesAndNanGivesZero) {
    StProgram run(R"(
PROGRAM Main
VAR big : LREAL := 1.0E30; small : LREAL := -1.0E30; zero : LREAL;
    i, j : INT; u : UDINT; l, nan_lint : LINT; END_VAR
i := LREAL_TO_INT(big); j := LREAL_TO_INT(small); u := LREAL_TO_UDINT(small);
l := LREAL_TO_LINT(big); nan_lint := LREAL_TO_LINT(zero / zero);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.i"), 32767);
    EXPECT_EQ(run.get<std::int16_t>("Main.j"), -32768);
    EXPECT_EQ(run.get<std::uint32_t>("Main.u"), 0U);
    EXPECT_EQ(run.get<std::int64_t>("Main.l"), INT64_MAX);
    EXPECT_EQ(run.get<std::int64_t>("Main.nan_lint"), 0);
}

} // namespace
} // namespace eposp::compiler::test
