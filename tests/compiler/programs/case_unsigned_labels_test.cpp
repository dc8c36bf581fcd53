// CASE labels of a ULINT or LWORD selector range over all 64 unsigned bits (IEC 61131-3 ed. 3,
// 7.3.3.3.3: every value of the selector's type may be a label), typed or not, single or in
// ranges, checked for overlap in unsigned order.
#include "codegen_harness.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

struct Selected {
    std::uint64_t selector;
    std::int32_t branch;
};

TEST(CaseUnsignedLabels, LabelsAbove2To63SelectTheirBranch) {
    StProgram run(R"(
PROGRAM Main
VAR CONSTANT top : ULINT := 16#FFFFFFFFFFFFFFFE; END_VAR
VAR u : ULINT; w : LWORD; ru, rw : DINT; END_VAR
CASE u OF
  0: ru := 1;
  ULINT#9542150923762281093, 9542150923762281094: ru := 2;
  ULINT#16#FFFFFFFFFFFFFFFF: ru := 3;
  16#8000000000000000..16#8000000000000010: ru := 4;
  16#7FFFFFFFFFFFFFFF: ru := 5;
  top: ru := 6;
  ULINT#18446744073709551615 - 2 .. top - 1: ru := 7;
ELSE
  ru := 8;
END_CASE;
w := ULINT_TO_LWORD(u);
CASE w OF
  LWORD#16#FFFFFFFFFFFFFFFF, 16#8000000000000000: rw := 1;
  16#C000000000000000..16#CFFFFFFFFFFFFFFF: rw := 2;
ELSE
  rw := 3;
END_CASE;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    const Selected cases[] = {
        {0, 1},
        {9542150923762281093ULL, 2},
        {9542150923762281094ULL, 2},
        {0xFFFFFFFFFFFFFFFFULL, 3},
        {0x8000000000000000ULL, 4},
        {0x8000000000000010ULL, 4},
        {0x8000000000000011ULL, 8},
        {0x7FFFFFFFFFFFFFFFULL, 5},
        {0xFFFFFFFFFFFFFFFEULL, 6},
        {0xFFFFFFFFFFFFFFFDULL, 7},
        {0xFFFFFFFFFFFFFFFCULL, 8},
        {1, 8},
    };
    for (const Selected& c : cases) {
        run.set<std::uint64_t>("Main.u", c.selector);
        ASSERT_TRUE(run.scans(1)) << run.fault();
        EXPECT_EQ(run.get<std::int32_t>("Main.ru"), c.branch) << c.selector;
    }
    const Selected words[] = {{0xFFFFFFFFFFFFFFFFULL, 1}, {0x8000000000000000ULL, 1},
                              {0xC000000000000000ULL, 2}, {0xCFFFFFFFFFFFFFFFULL, 2},
                              {0xD000000000000000ULL, 3}, {0xBFFFFFFFFFFFFFFFULL, 3}};
    for (const Selected& c : words) {
        run.set<std::uint64_t>("Main.u", c.selector);
        ASSERT_TRUE(run.scans(1)) << run.fault();
        EXPECT_EQ(run.get<std::int32_t>("Main.rw"), c.branch) << c.selector;
    }
}

TEST(CaseUnsignedLabels, OverlapIsCheckedInUnsignedOrder) {
    EXPECT_THAT(diagnostics_of(R"(
PROGRAM Main
VAR u : ULINT; r : DINT; END_VAR
CASE u OF
  1..16#FFFFFFFFFFFFFFFF: r := 1;
  16#9000000000000000: r := 2;
END_CASE;
END_PROGRAM
)"),
                testing::HasSubstr("test.st:6:3: error: this CASE label overlaps an earlier one"));
    EXPECT_EQ(diagnostics_of(R"(
PROGRAM Main
VAR u : ULINT; r : DINT; END_VAR
CASE u OF
  0..16#7FFFFFFFFFFFFFFF: r := 1;
  16#8000000000000000..16#FFFFFFFFFFFFFFFF: r := 2;
END_CASE;
END_PROGRAM
)"),
              "");
}

TEST(CaseUnsignedLabels, ASignedSelectorRefusesThem) {
    EXPECT_THAT(diagnostics_of(R"(
PROGRAM Main
VAR i : LINT; r : DINT; END_VAR
CASE i OF
  16#8000000000000000: r := 1;
END_CASE;
END_PROGRAM
)"),
                testing::HasSubstr("test.st:5:3: error: a CASE label must be a value of LINT"));
}

// Definite assignment sees that labels up to the top of ULINT cover a ULINT subrange.
TEST(CaseUnsignedLabels, ARangeUpToTheTopCoversASubrange) {
    EXPECT_EQ(diagnostics_of(R"(
TYPE Small : ULINT(0..10); END_TYPE
FUNCTION Pick : DINT
  VAR_INPUT u : Small; END_VAR
  CASE u OF
    0..4: Pick := 1;
    5..16#FFFFFFFFFFFFFFFF: Pick := 2;
  END_CASE;
END_FUNCTION

PROGRAM Main
VAR r : DINT; END_VAR
r := Pick(3);
END_PROGRAM
)"),
              "");
}

// The top of the 32-bit unsigned range, through a jump table.
TEST(CaseUnsignedLabels, JumpTableAtTheTopOfUdint) {
    StProgram run(R"(
PROGRAM Main
VAR u : UDINT; r : DINT; END_VAR
CASE u OF
  16#FFFFFFFC: r := 1;
  16#FFFFFFFD: r := 2;
  16#FFFFFFFE: r := 3;
  16#FFFFFFFF: r := 4;
ELSE
  r := 5;
END_CASE;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    const std::pair<std::uint32_t, std::int32_t> cases[] = {
        {0xFFFFFFFCU, 1}, {0xFFFFFFFDU, 2}, {0xFFFFFFFEU, 3}, {0xFFFFFFFFU, 4}, {0, 5}, {7, 5}};
    for (const auto& [selector, branch] : cases) {
        run.set<std::uint32_t>("Main.u", selector);
        ASSERT_TRUE(run.scans(1)) << run.fault();
        EXPECT_EQ(run.get<std::int32_t>("Main.r"), branch) << selector;
    }
}

} // namespace
} // namespace eposp::compiler::test
