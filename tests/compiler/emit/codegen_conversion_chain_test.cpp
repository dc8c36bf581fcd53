// A conversion whose result feeds the next conversion at once, for every pair of integer types
// (source, middle) and every 64-bit or real target: the middle value must reach the target as
// the middle type says (zero- or sign-extended from its own width), whatever bits the source had
// above that width. Compiled code takes the middle value from the register its store left it
// in, which once kept the source's upper half (issue 16, defect 1).
#include "codegen_harness.hpp"

#include <array>
#include <cstdint>
#include <gtest/gtest.h>
#include <string>

namespace eposp::compiler::test {
namespace {

struct IntegerType {
    const char* name;
    int bytes;
    bool sign;
};

constexpr std::array kIntegers{
    IntegerType{"SINT", 1, true},   IntegerType{"INT", 2, true},    IntegerType{"DINT", 4, true},
    IntegerType{"LINT", 8, true},   IntegerType{"USINT", 1, false}, IntegerType{"UINT", 2, false},
    IntegerType{"UDINT", 4, false}, IntegerType{"ULINT", 8, false}, IntegerType{"BYTE", 1, false},
    IntegerType{"WORD", 2, false},  IntegerType{"DWORD", 4, false}, IntegerType{"LWORD", 8, false},
};

constexpr std::array<std::uint64_t, 12> kSourceBits{0,
                                                    1,
                                                    ~std::uint64_t{0},
                                                    ~std::uint64_t{1},
                                                    0x7F,
                                                    0x80,
                                                    0xFFFFFFFFFFFF8000,
                                                    0x7FFFFFFF,
                                                    0x80000000,
                                                    0xFFFFFFFF80000000,
                                                    0x7FFFFFFF80000001,
                                                    0x123456789ABCDEF0};

/// `bits` cut to `type`'s width, then extended to 64 bits as the type's value.
std::uint64_t value_of(const IntegerType& type, std::uint64_t bits) {
    if (type.bytes == 8) {
        return bits;
    }
    const int shift = 64 - 8 * type.bytes;
    return type.sign ? static_cast<std::uint64_t>(static_cast<std::int64_t>(bits << shift) >> shift)
                     : bits << shift >> shift;
}

double as_real(const IntegerType& type, std::uint64_t value) {
    return type.sign ? static_cast<double>(static_cast<std::int64_t>(value))
                     : static_cast<double>(value);
}

void set_source(StProgram& run, const IntegerType& type, std::uint64_t bits) {
    switch (type.bytes) {
    case 1:
        return run.set("Main.s", static_cast<std::uint8_t>(bits));
    case 2:
        return run.set("Main.s", static_cast<std::uint16_t>(bits));
    case 4:
        return run.set("Main.s", static_cast<std::uint32_t>(bits));
    default:
        return run.set("Main.s", bits);
    }
}

struct Pair {
    IntegerType source;
    IntegerType middle;
};

void PrintTo(const Pair& pair, std::ostream* out) {
    *out << pair.source.name << " to " << pair.middle.name;
}

class ConversionChain : public testing::TestWithParam<Pair> {};

TEST_P(ConversionChain, MiddleValueReachesEveryWideTarget) {
    const auto [source, middle] = GetParam();
    const std::string from = std::string(source.name) + "_TO_" + middle.name + "(s)";
    std::string body;
    for (const char* target : {"LINT", "ULINT", "LWORD", "LREAL", "REAL"}) {
        body += std::string("m := ") + from + "; t_" + target + " := " + middle.name + "_TO_" +
                target + "(m);\n";
    }
    StProgram run(std::string("PROGRAM Main\nVAR s : ") + source.name + "; m : " + middle.name +
                  "; t_LINT : LINT; t_ULINT : ULINT; t_LWORD : LWORD; t_LREAL : LREAL;"
                  " t_REAL : REAL; END_VAR\n" +
                  body + "END_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    for (std::uint64_t bits : kSourceBits) {
        set_source(run, source, bits);
        ASSERT_TRUE(run.scans(1)) << run.fault();
        const std::uint64_t expected = value_of(middle, value_of(source, bits));
        const std::string where = from + " with s = " + std::to_string(value_of(source, bits));
        EXPECT_EQ(run.get<std::uint64_t>("Main.t_LINT"), expected) << where;
        EXPECT_EQ(run.get<std::uint64_t>("Main.t_ULINT"), expected) << where;
        EXPECT_EQ(run.get<std::uint64_t>("Main.t_LWORD"), expected) << where;
        EXPECT_EQ(run.get<double>("Main.t_LREAL"), as_real(middle, expected)) << where;
        const float real = middle.sign ? static_cast<float>(static_cast<std::int64_t>(expected))
                                       : static_cast<float>(expected);
        EXPECT_EQ(run.get<float>("Main.t_REAL"), real) << where;
    }
}

std::vector<Pair> all_pairs() {
    std::vector<Pair> pairs;
    for (const IntegerType& source : kIntegers) {
        for (const IntegerType& middle : kIntegers) {
            pairs.push_back(Pair{source, middle});
        }
    }
    return pairs;
}

INSTANTIATE_TEST_SUITE_P(EveryIntegerPair, ConversionChain, testing::ValuesIn(all_pairs()),
                         [](const testing::TestParamInfo<Pair>& pair) {
                             return std::string(pair.param.source.name) + "To" +
                                    pair.param.middle.name;
                         });

// The reproductions of the issue, as written there.
TEST(ConversionChain, IssueReproductionsKeepTheZeroExtension) {
    StProgram run(R"(
PROGRAM Main
VAR d : DINT := -1; ud : UDINT; l, l2 : LINT; big : LINT := -1; u : ULINT; r : LREAL;
    w : LINT; END_VAR
ud := DINT_TO_UDINT(d); l := UDINT_TO_LINT(ud);
ud := LINT_TO_UDINT(big); l2 := UDINT_TO_LINT(ud);
u := DWORD_TO_ULINT(ULINT_TO_DWORD(16#FFFFFFFFFFFFFFFE));
r := UDINT_TO_LREAL(DINT_TO_UDINT(-32768));
w := DWORD_TO_LINT(SINT_TO_DWORD(-2));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int64_t>("Main.l"), 4294967295);
    EXPECT_EQ(run.get<std::int64_t>("Main.l2"), 4294967295);
    EXPECT_EQ(run.get<std::uint64_t>("Main.u"), 4294967294U);
    EXPECT_EQ(run.get<double>("Main.r"), 4294934528.0);
    EXPECT_EQ(run.get<std::int64_t>("Main.w"), 4294967294);
}

} // namespace
} // namespace eposp::compiler::test
