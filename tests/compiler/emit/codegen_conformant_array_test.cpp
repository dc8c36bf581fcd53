// VAR_IN_OUT ARRAY[*] parameters (IEC 61131-3 ed. 3, 6.5.3): arrays of any bounds are passed
// with their bounds, LOWER_BOUND / UPPER_BOUND read them, and an index outside them stops the
// task naming the POU and the line.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

constexpr const char* kSum = R"(
FUNCTION Sum : DINT
  VAR_IN_OUT a : ARRAY[*] OF INT; END_VAR
  VAR i : DINT; END_VAR
  FOR i := LOWER_BOUND(a, 1) TO UPPER_BOUND(a, 1) DO
    Sum := Sum + a[i];
  END_FOR;
END_FUNCTION
)";

TEST(ConformantArray, AFunctionTakesArraysOfAnyBounds) {
    StProgram run(std::string(kSum) + R"(
PROGRAM Main
VAR
  small : ARRAY[1..3] OF INT := [1, 2, 3];
  shifted : ARRAY[-2..7] OF INT := [10(5)];
  s, t : DINT;
END_VAR
s := Sum(small);
t := Sum(a := shifted);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int32_t>("Main.s"), 6);
    EXPECT_EQ(run.get<std::int32_t>("Main.t"), 50);
}

TEST(ConformantArray, AFunctionBlockWritesTheElementsAndPassesTheArrayOn) {
    StProgram run(std::string(kSum) + R"(
FUNCTION_BLOCK Filler
  VAR_INPUT v : INT; END_VAR
  VAR_IN_OUT a : ARRAY[*] OF INT; END_VAR
  VAR_OUTPUT total : DINT; END_VAR
  VAR i : DINT; END_VAR
  FOR i := LOWER_BOUND(a, 1) TO UPPER_BOUND(a, 1) DO
    a[i] := v;
  END_FOR;
  total := Sum(a);
END_FUNCTION_BLOCK
PROGRAM Main
VAR
  big : ARRAY[-2..7] OF INT;
  few : ARRAY[0..1] OF INT;
  fill : Filler;
  t, u : DINT;
END_VAR
fill(v := 4, a := big, total => t);
fill(v := 9, a := few, total => u);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int32_t>("Main.t"), 40);
    EXPECT_EQ(run.get<std::int32_t>("Main.u"), 18);
    EXPECT_EQ(run.get<std::int16_t>("Main.big[-2]"), 4);
    EXPECT_EQ(run.get<std::int16_t>("Main.few[1]"), 9);
}

TEST(ConformantArray, EveryDimensionHasItsOwnBounds) {
    StProgram run(R"(
FUNCTION Weighted : DINT
  VAR_IN_OUT m : ARRAY[*, *] OF DINT; END_VAR
  VAR i, j : DINT; END_VAR
  FOR i := LOWER_BOUND(m, 1) TO UPPER_BOUND(m, 1) DO
    FOR j := LOWER_BOUND(m, 2) TO UPPER_BOUND(m, 2) DO
      Weighted := Weighted + m[i, j] * i * j;
    END_FOR;
  END_FOR;
END_FUNCTION
PROGRAM Main
VAR
  grid : ARRAY[0..1, 1..3] OF DINT := [1, 2, 3, 4, 5, 6];
  w, rows, columns : DINT;
END_VAR
w := Weighted(grid);
rows := UPPER_BOUND(grid, 1) - LOWER_BOUND(grid, 1) + 1;
columns := UPPER_BOUND(grid, 2);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int32_t>("Main.w"), 4 * 1 + 5 * 2 + 6 * 3);
    EXPECT_EQ(run.get<std::int32_t>("Main.rows"), 2);
    EXPECT_EQ(run.get<std::int32_t>("Main.columns"), 3);
}

TEST(ConformantArray, AnIndexOutsideTheActualBoundsStopsTheTask) {
    StProgram run(R"(
FUNCTION Last : INT
  VAR_IN_OUT a : ARRAY[*] OF INT; END_VAR
  VAR_INPUT past : DINT; END_VAR
  Last := a[UPPER_BOUND(a, 1) + past];
END_FUNCTION
PROGRAM Main
VAR small : ARRAY[1..3] OF INT := [1, 2, 3]; x : INT; past : DINT; END_VAR
x := Last(small, past);
past := 1;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int16_t>("Main.x"), 3);
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "array index out of range in Last at line 5");
}

TEST(ConformantArray, EachIndexIsCheckedAgainstItsOwnDimension) {
    StProgram run(R"(
FUNCTION Cell : DINT
  VAR_IN_OUT m : ARRAY[*, *] OF DINT; END_VAR
  VAR_INPUT i, j : DINT; END_VAR
  Cell := m[i, j];
END_FUNCTION
PROGRAM Main
VAR grid : ARRAY[0..1, 1..3] OF DINT; x : DINT; END_VAR
x := Cell(grid, 0, 4);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1)) << "grid[0, 4] is inside the array's bytes, but not a grid element";
    EXPECT_EQ(run.fault(), "array index out of range in Cell at line 5");
}

struct Refused {
    std::string name;
    std::string source;
    std::string message;
};

class ConformantArrayRefused : public testing::TestWithParam<Refused> {};

TEST_P(ConformantArrayRefused, ReportsTheErrorWhereItIs) {
    const Refused& c = GetParam();
    StProgram run(c.source);
    EXPECT_FALSE(run.ok());
    EXPECT_NE(run.errors().find(c.message), std::string::npos) << run.errors();
}

std::string calling_sum(const std::string& declarations, const std::string& body) {
    return std::string(kSum) + "PROGRAM Main\nVAR " + declarations + " END_VAR\n" + body +
           "\nEND_PROGRAM\n";
}

INSTANTIATE_TEST_SUITE_P(
    Refused, ConformantArrayRefused,
    testing::Values(
        Refused{"OutsideVarInOut", "PROGRAM Main\nVAR a : ARRAY[*] OF INT; END_VAR\nEND_PROGRAM\n",
                "test.st:2:9: error: ARRAY[*] is only allowed for VAR_IN_OUT"},
        Refused{"AsAnInput",
                "FUNCTION F : INT\nVAR_INPUT a : ARRAY[*] OF INT; END_VAR\nF := 0;\n"
                "END_FUNCTION\n",
                "test.st:2:15: error: ARRAY[*] is only allowed for VAR_IN_OUT"},
        Refused{"BehindAReference",
                "PROGRAM Main\nVAR r : REF_TO ARRAY[*] OF INT; END_VAR\nEND_PROGRAM\n",
                "ARRAY[*] is only allowed for VAR_IN_OUT"},
        Refused{"MixedDimensions",
                "FUNCTION F : INT\nVAR_IN_OUT a : ARRAY[*, 1..2] OF INT; END_VAR\nF := 0;\n"
                "END_FUNCTION\n",
                "an array has either bounds or '*' in every dimension"},
        Refused{"AssignedAsAWhole",
                "FUNCTION F : INT\nVAR_IN_OUT a, b : ARRAY[*] OF INT; END_VAR\na := b;\nF := 0;\n"
                "END_FUNCTION\n",
                "test.st:3:1: error: an ARRAY[*] cannot be assigned as a whole, only its elements"},
        Refused{"OtherElementType",
                calling_sum("d : ARRAY[1..3] OF DINT; s : DINT;", "s := Sum(d);"),
                "test.st:11:10: error: VAR_IN_OUT 'a' needs an array of 1 dimension(s) of INT"},
        Refused{"OtherDimensionCount",
                calling_sum("g : ARRAY[1..3, 1..2] OF INT; s : DINT;", "s := Sum(g);"),
                "VAR_IN_OUT 'a' needs an array of 1 dimension(s) of INT"},
        Refused{"NotAnArray", calling_sum("i : INT; s : DINT;", "s := Sum(i);"),
                "VAR_IN_OUT 'a' needs an array of 1 dimension(s) of INT"},
        Refused{"PassedToFixedBounds",
                "FUNCTION Fixed : INT\nVAR_IN_OUT f : ARRAY[1..3] OF INT; END_VAR\nFixed := 0;\n"
                "END_FUNCTION\nFUNCTION F : INT\nVAR_IN_OUT a : ARRAY[*] OF INT; END_VAR\n"
                "F := Fixed(a);\nEND_FUNCTION\n",
                "VAR_IN_OUT 'f' needs a ARRAY[1..3] OF INT variable"},
        Refused{"DimensionNotConstant",
                calling_sum("a : ARRAY[1..3] OF INT; s, d : DINT;", "s := LOWER_BOUND(a, d);"),
                "test.st:11:21: error: the dimension must be a constant from 1 to 1"},
        Refused{"DimensionTooLarge",
                calling_sum("a : ARRAY[1..3] OF INT; s : DINT;", "s := UPPER_BOUND(a, 2);"),
                "the dimension must be a constant from 1 to 1"},
        Refused{"BoundOfANonArray", calling_sum("i : INT; s : DINT;", "s := UPPER_BOUND(i, 1);"),
                "UPPER_BOUND needs an array, not INT"}),
    [](const auto& c) { return c.param.name; });

} // namespace
} // namespace eposp::compiler::test
