// A LINT or ULINT used as an array index, a FOR bound, a string position or length, a MUX
// selector or a pointer offset keeps its whole value: cut to 32 bits it would name another
// element (4294967298 would be 2). An index outside the array stops the task with the index
// error, on both engines; a string position or length past the string acts as one that is just
// past it. Issue 16, defect 6.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>
#include <string>

namespace eposp::compiler::test {
namespace {

struct WideIndex {
    std::string name;
    std::string declarations; // of Main, besides `x : DINT; a : ARRAY[...]` below
    std::string array;        // the bounds of a
    std::string statement;    // reads or writes a
};

void PrintTo(const WideIndex& c, std::ostream* out) {
    *out << c.name;
}

class ArrayIndex : public testing::TestWithParam<WideIndex> {};

TEST_P(ArrayIndex, OutsideTheArrayStopsTheTaskWithTheIndexError) {
    const WideIndex& c = GetParam();
    StProgram run("PROGRAM Main\nVAR x : DINT; a : ARRAY[" + c.array + "] OF DINT; " +
                  c.declarations + " END_VAR\n" + c.statement + "\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1));
    EXPECT_NE(run.fault().find("array index out of range"), std::string::npos) << run.fault();
}

INSTANTIATE_TEST_SUITE_P(
    SixtyFourBits, ArrayIndex,
    testing::Values(
        WideIndex{"LintRead", "i : LINT := 4294967298;", "0..9", "x := a[i];"},
        WideIndex{"LintWrite", "i : LINT := 4294967298;", "0..9", "a[i] := 1;"},
        WideIndex{"NegativeLint", "i : LINT := -4294967294;", "0..9", "x := a[i];"},
        WideIndex{"LintBelowNegativeLower", "i : LINT := -4294967297;", "-5..5", "x := a[i];"},
        WideIndex{"LintOfAnExpression", "i : LINT := 4294967290;", "0..9", "x := a[i + 8];"},
        WideIndex{"UlintRead", "i : ULINT := 4294967298;", "0..9", "x := a[i];"},
        WideIndex{"UlintMaxWithNegativeLower", "i : ULINT := 16#FFFFFFFFFFFFFFFF;", "-5..5",
                  "x := a[i];"},
        WideIndex{"UdintAboveDintWithNegativeLower", "i : UDINT := 4294967295;", "-5..5",
                  "x := a[i];"},
        WideIndex{"LintNearTheTopOfDint", "i : LINT := 2147483648;", "2147483640..2147483647",
                  "x := a[i];"},
        WideIndex{"LintNearTheBottomOfDint", "i : LINT := -2147483649;", "-2147483648..-2147483640",
                  "x := a[i];"},
        WideIndex{"OneDimensionOfTwo", "m : ARRAY[0..2, 0..2] OF INT; i : LINT := 4294967297;",
                  "0..1", "m[i, 0] := 1;"},
        WideIndex{"SecondDimensionOfTwo", "m : ARRAY[0..2, 0..2] OF INT; i : ULINT := 4294967297;",
                  "0..1", "m[0, i] := 1;"}),
    [](const testing::TestParamInfo<WideIndex>& c) { return c.param.name; });

TEST(WideIndex, InsideTheArrayNamesTheElement) {
    StProgram run(R"(
PROGRAM Main
VAR a : ARRAY[-5..5] OF DINT := [-5, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5];
    m : ARRAY[0..2, 0..2] OF DINT := [0, 1, 2, 10, 11, 12, 20, 21, 22];
    i : LINT := -5; u : ULINT := 5; w : LINT := 3; d : UDINT := 2; k : LINT := 2;
    x, y, z, v, mm : DINT; END_VAR
x := a[i]; y := a[u]; z := a[w]; v := a[d]; mm := m[k, u - 4];
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), -5);
    EXPECT_EQ(run.get<std::int32_t>("Main.y"), 5);
    EXPECT_EQ(run.get<std::int32_t>("Main.z"), 3);
    EXPECT_EQ(run.get<std::int32_t>("Main.v"), 2);
    EXPECT_EQ(run.get<std::int32_t>("Main.mm"), 21);
}

constexpr const char* kConformant = R"(
FUNCTION Pick : DINT
VAR_IN_OUT arr : ARRAY[*] OF DINT; END_VAR
VAR_INPUT i : LINT; END_VAR
Pick := arr[i];
END_FUNCTION
PROGRAM Main
VAR a : ARRAY[0..9] OF DINT := [0, 10, 20, 30, 40, 50, 60, 70, 80, 90]; i : LINT; x : DINT; END_VAR
x := Pick(arr := a, i := i);
END_PROGRAM
)";

TEST(WideIndex, ConformantArrayOutsideStopsTheTask) {
    StProgram run(kConformant);
    ASSERT_TRUE(run.ok()) << run.errors();
    run.set<std::int64_t>("Main.i", 7);
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), 70);
    run.set<std::int64_t>("Main.i", 4294967298);
    EXPECT_FALSE(run.scans(1));
    EXPECT_NE(run.fault().find("array index out of range"), std::string::npos) << run.fault();
}

TEST(WideIndex, ForBoundsKeepSixtyFourBits) {
    StProgram run(R"(
PROGRAM Main
VAR i, from : LINT := 4294967290; upto : LINT := 4294967300; u : ULINT; n, m : DINT; END_VAR
FOR i := from TO upto DO n := n + 1; END_FOR;
FOR u := 16#FFFFFFFFFFFFFFF0 TO 16#FFFFFFFFFFFFFFF4 BY 2 DO m := m + 1; END_FOR;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.n"), 11);
    EXPECT_EQ(run.get<std::int32_t>("Main.m"), 3);
}

TEST(WideIndex, ForBoundWiderThanTheControlVariableIsRefused) {
    EXPECT_NE(diagnostics_of(R"(
PROGRAM Main
VAR i : DINT; upto : LINT := 4294967300; n : DINT; END_VAR
FOR i := 0 TO upto DO n := n + 1; END_FOR;
END_PROGRAM
)")
                  .find("error"),
              std::string::npos);
}

TEST(WideIndex, StringPositionsAndLengthsKeepSixtyFourBits) {
    StProgram run(R"(
PROGRAM Main
VAR s : STRING := 'abcdef'; big : LINT := 4294967298; one : LINT := 4294967297;
    minus : LINT := -4294967294; ubig : ULINT := 16#FFFFFFFF00000002;
    s_left, s_right, s_mid, s_mid2, s_ins, s_del, s_del2, s_rep, s_neg, s_uleft : STRING; END_VAR
s_left := LEFT(s, big);
s_right := RIGHT(s, big);
s_mid := MID(s, 2, one);
s_mid2 := MID(s, big, 2);
s_ins := INSERT(s, 'X', one);
s_del := DELETE(s, 2, one);
s_del2 := DELETE(s, big, 1);
s_rep := REPLACE(s, 'X', big, 2);
s_neg := LEFT(s, minus);
s_uleft := LEFT(s, ubig);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.s_left"), "abcdef");
    EXPECT_EQ(run.get_string("Main.s_right"), "abcdef");
    EXPECT_EQ(run.get_string("Main.s_mid"), "");
    EXPECT_EQ(run.get_string("Main.s_mid2"), "bcdef");
    EXPECT_EQ(run.get_string("Main.s_ins"), "abcdefX");
    EXPECT_EQ(run.get_string("Main.s_del"), "abcdef");
    EXPECT_EQ(run.get_string("Main.s_del2"), "");
    EXPECT_EQ(run.get_string("Main.s_rep"), "aX");
    EXPECT_EQ(run.get_string("Main.s_neg"), "");
    EXPECT_EQ(run.get_string("Main.s_uleft"), "abcdef");
}

TEST(WideIndex, MuxSelectorOutsideGivesTheFirstInput) {
    StProgram run(R"(
PROGRAM Main
VAR k : LINT := 4294967297; u : ULINT := 16#FFFFFFFF00000002; x, y : DINT; END_VAR
x := MUX(k, 10, 11, 12);
y := MUX(u, 10, 11, 12);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), 10);
    EXPECT_EQ(run.get<std::int32_t>("Main.y"), 10);
}

TEST(WideIndex, PointerOffsetKeepsSixtyFourBits) {
    StProgram run(R"(
PROGRAM Main
VAR a : ARRAY[0..9] OF DINT := [0, 10, 20, 30, 40, 50, 60, 70, 80, 90];
    p : POINTER TO DINT; near : LINT := 8; far : ULINT := 4294967304; x, y : DINT; END_VAR
p := ADR(a[0]) + near; x := p^;
p := ADR(a[0]) + far; y := p^;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), 20);
    EXPECT_EQ(run.get<std::int32_t>("Main.y"), 0);
    EXPECT_NE(run.fault().find("address"), std::string::npos) << run.fault();
}

} // namespace
} // namespace eposp::compiler::test
