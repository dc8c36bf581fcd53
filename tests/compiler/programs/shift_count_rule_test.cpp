// SHL, SHR, ROL and ROR take their count as unsigned, whatever its integer type (a negative
// count as its two's complement): SHL and SHR by a count of at least the operand's width give 0
// (every bit shifted out, IEC 61131-3 ed. 3 table 29: zero-filled), ROL and ROR rotate by the
// count modulo the width. A 64-bit count once lost its high half: 4294967297 shifted by 1.
#include "codegen_harness.hpp"

#include <array>
#include <cstdint>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

namespace eposp::compiler::test {
namespace {

struct Operand {
    const char* name;
    unsigned width;
};
struct Count {
    const char* name;
    unsigned width;
    bool sign;
};

void PrintTo(const Operand& operand, std::ostream* out) {
    *out << operand.name;
}
void PrintTo(const Count& count, std::ostream* out) {
    *out << count.name;
}

constexpr std::array kOperands{Operand{"BYTE", 8}, Operand{"WORD", 16}, Operand{"DWORD", 32},
                               Operand{"LWORD", 64}};
constexpr std::array kCounts{Count{"SINT", 8, true},    Count{"INT", 16, true},
                             Count{"DINT", 32, true},   Count{"LINT", 64, true},
                             Count{"USINT", 8, false},  Count{"UINT", 16, false},
                             Count{"UDINT", 32, false}, Count{"ULINT", 64, false}};

constexpr std::uint64_t kPattern = 0x8123'4567'89AB'CDEFu; // top and bottom bit set at each width

std::uint64_t mask(unsigned width) {
    return width == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
}

/// The counts at the boundaries, as 64-bit two's complement, that the count type holds.
std::vector<std::uint64_t> counts(unsigned width, const Count& type) {
    const std::uint64_t min_signed = std::uint64_t{1} << 63;
    std::vector<std::uint64_t> all{width - 1,  width, width + 1, (std::uint64_t{1} << 32) + 1,
                                   min_signed, ~0ull, 0};
    std::vector<std::uint64_t> held;
    for (const std::uint64_t n : all) {
        const auto value = static_cast<std::int64_t>(n);
        const bool fits =
            type.sign ? (type.width == 64 || (value >= -(std::int64_t{1} << (type.width - 1)) &&
                                              value < (std::int64_t{1} << (type.width - 1))))
                      : (type.width == 64 || n <= mask(type.width));
        if (fits) {
            held.push_back(n);
        }
    }
    return held;
}

/// An ST literal of the count type for `n` (LINT's minimum has no literal of its own).
std::string literal(const Count& type, std::uint64_t n) {
    if (!type.sign) {
        return std::to_string(n);
    }
    const auto value = static_cast<std::int64_t>(n);
    return value == INT64_MIN ? "-9223372036854775807 - 1" : std::to_string(value);
}

std::uint64_t expected(const std::string& function, std::uint64_t x, std::uint64_t n,
                       unsigned width) {
    x &= mask(width);
    if (function == "SHL" || function == "SHR") {
        return n >= width ? 0 : (function == "SHL" ? x << n : x >> n) & mask(width);
    }
    const auto r = static_cast<unsigned>(n % width);
    const unsigned left = function == "ROL" ? r : (width - r) % width;
    return left == 0 ? x : ((x << left) | (x >> (width - left))) & mask(width);
}

std::uint64_t read(const StProgram& run, const std::string& path, unsigned width) {
    switch (width) {
    case 8:
        return run.get<std::uint8_t>(path);
    case 16:
        return run.get<std::uint16_t>(path);
    case 32:
        return run.get<std::uint32_t>(path);
    default:
        return run.get<std::uint64_t>(path);
    }
}

constexpr std::array<const char*, 4> kFunctions{"SHL", "SHR", "ROL", "ROR"};

class ShiftCount : public ::testing::TestWithParam<std::tuple<Operand, Count>> {};

TEST_P(ShiftCount, FollowsTheRuleAtEveryBoundary) {
    const auto [operand, count] = GetParam();
    const auto values = counts(operand.width, count);
    std::string declarations =
        fmt::format("x : {} := {}#{};", operand.name, operand.name, kPattern & mask(operand.width));
    std::string body;
    for (std::size_t i = 0; i < values.size(); ++i) {
        declarations += fmt::format(" c{} : {};", i, count.name);
        body += fmt::format("c{} := {};\n", i, literal(count, values[i]));
        for (const char* function : kFunctions) {
            declarations += fmt::format(" {}{} : {};", function, i, operand.name);
            body += fmt::format("{}{} := {}(x, c{});\n", function, i, function, i);
        }
    }
    StProgram run("PROGRAM Main\nVAR " + declarations + " END_VAR\n" + body + "END_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    for (std::size_t i = 0; i < values.size(); ++i) {
        for (const std::string function : kFunctions) {
            EXPECT_EQ(read(run, fmt::format("Main.{}{}", function, i), operand.width),
                      expected(function, kPattern, values[i], operand.width))
                << function << "(" << operand.name << ", " << count.name << "#"
                << literal(count, values[i]) << ")";
        }
    }
}

std::string name(const ::testing::TestParamInfo<ShiftCount::ParamType>& info) {
    return std::string(std::get<0>(info.param).name) + "By" + std::get<1>(info.param).name;
}

INSTANTIATE_TEST_SUITE_P(EveryWidthAndCountType, ShiftCount,
                         ::testing::Combine(::testing::ValuesIn(kOperands),
                                            ::testing::ValuesIn(kCounts)),
                         name);

TEST(ShiftCountRule, ALiteralCountBeyond32BitsOrNegativeKeepsItsWholeValue) {
    StProgram run(R"(PROGRAM Main
VAR a, b, c, d, f : DWORD; e : LWORD; g : BYTE; END_VAR
a := SHL(DWORD#1, 4294967297); b := ROL(DWORD#1, 4294967297);
c := SHR(DWORD#16#80000000, LINT#4294967327); d := ROR(DWORD#1, ULINT#18446744073709551615);
e := SHL(LWORD#1, ULINT#9223372036854775808); f := SHL(DWORD#1, -1); g := ROL(BYTE#1, -1);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::uint32_t>("Main.a"), 0u);
    EXPECT_EQ(run.get<std::uint32_t>("Main.b"), 2u);
    EXPECT_EQ(run.get<std::uint32_t>("Main.c"), 0u);
    EXPECT_EQ(run.get<std::uint32_t>("Main.d"), 2u); // ROR by 2^64-1: by 31, ROL by 1
    EXPECT_EQ(run.get<std::uint64_t>("Main.e"), 0u);
    EXPECT_EQ(run.get<std::uint32_t>("Main.f"), 0u);
    EXPECT_EQ(run.get<std::uint8_t>("Main.g"), 0x80u); // ROL by 2^32 - 1, modulo 8: 7
}

} // namespace
} // namespace eposp::compiler::test
