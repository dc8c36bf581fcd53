// Subrange types (IEC 61131-3 ed. 3, 6.4.4.4): constants outside the range are compile errors,
// other values are checked where they are stored, and a run-time violation stops the task
// naming the POU and the line.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

constexpr const char* kPercent = "TYPE Percent : INT (0..100); END_TYPE\n";

std::string main_with(const std::string& declarations, const std::string& body) {
    return std::string(kPercent) + "PROGRAM Main\nVAR " + declarations + " END_VAR\n" + body +
           "\nEND_PROGRAM\n";
}

TEST(Subrange, StartsAtItsLowerBound) {
    StProgram run(main_with("p : Percent; q : INT(10..20); r : INT(-5..5) := 3;", ""));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int16_t>("Main.p"), 0);
    EXPECT_EQ(run.get<std::int16_t>("Main.q"), 10);
    EXPECT_EQ(run.get<std::int16_t>("Main.r"), 3);
}

TEST(Subrange, ValuesInsideTheRangeAreStored) {
    StProgram run(main_with("p : Percent; i : INT := 100; s : SINT := 7;",
                            "p := i;\np := p - 1;\np := s;\np := 100;"));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int16_t>("Main.p"), 100);
}

struct Violation {
    std::string name;
    std::string source;
    std::string fault;
};

class SubrangeViolation : public testing::TestWithParam<Violation> {};

TEST_P(SubrangeViolation, StopsTheTaskNamingPouAndLine) {
    const Violation& c = GetParam();
    StProgram run(c.source);
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(3));
    EXPECT_EQ(run.fault(), c.fault);
}

INSTANTIATE_TEST_SUITE_P(
    Stores, SubrangeViolation,
    testing::Values(
        Violation{"Assignment", main_with("p : Percent; i : INT := 101;", "p := i;"),
                  "value out of subrange in Main at line 4"},
        Violation{"BelowTheLowerBound", main_with("q : INT(10..20); i : INT := 9;", "q := i;"),
                  "value out of subrange in Main at line 4"},
        Violation{"ComputedFromTheVariable", main_with("p : Percent := 99;", "p := p + 1;"),
                  "value out of subrange in Main at line 4"},
        Violation{"ArrayElement",
                  main_with("a : ARRAY[1..3] OF Percent; i, v : INT := 2;", "v := v * 100;\n"
                                                                            "a[i] := v;"),
                  "value out of subrange in Main at line 5"},
        Violation{"StructMemberThroughAReference",
                  std::string(kPercent) +
                      "TYPE Reading : STRUCT level : Percent; END_STRUCT; END_TYPE\n" +
                      "PROGRAM Main\nVAR r : Reading; p : REF_TO Reading; i : INT := -1; "
                      "END_VAR\np := REF(r);\np^.level := i;\nEND_PROGRAM\n",
                  "value out of subrange in Main at line 6"},
        Violation{"FunctionInput",
                  std::string(kPercent) +
                      "FUNCTION Twice : INT\nVAR_INPUT p : Percent; END_VAR\nTwice := p * 2;\n"
                      "END_FUNCTION\nPROGRAM Main\nVAR i : INT := 200; END_VAR\ni := Twice(i);\n"
                      "END_PROGRAM\n",
                  "value out of subrange in Main at line 8"},
        Violation{"FunctionResult",
                  std::string(kPercent) +
                      "FUNCTION Scaled : Percent\nVAR_INPUT i : INT; END_VAR\nScaled := i * 10;\n"
                      "END_FUNCTION\nPROGRAM Main\nVAR p : Percent; END_VAR\np := Scaled(11);\n"
                      "END_PROGRAM\n",
                  "value out of subrange in Scaled at line 4"},
        Violation{"FbInput",
                  std::string(kPercent) +
                      "FUNCTION_BLOCK Valve\nVAR_INPUT opening : Percent; END_VAR\n"
                      "END_FUNCTION_BLOCK\nPROGRAM Main\nVAR v : Valve; i : INT := 150; END_VAR\n"
                      "v(opening := i);\nEND_PROGRAM\n",
                  "value out of subrange in Main at line 7"},
        Violation{"FbOutput",
                  std::string(kPercent) +
                      "FUNCTION_BLOCK Sensor\nVAR_OUTPUT raw : INT; END_VAR\nraw := 300;\n"
                      "END_FUNCTION_BLOCK\nPROGRAM Main\nVAR s : Sensor; p : Percent; END_VAR\n"
                      "s(raw => p);\nEND_PROGRAM\n",
                  "value out of subrange in Main at line 8"},
        Violation{"FunctionOutput",
                  std::string(kPercent) +
                      "FUNCTION Split : BOOL\nVAR_OUTPUT high : INT; END_VAR\nhigh := -3;\n"
                      "Split := TRUE;\nEND_FUNCTION\nPROGRAM Main\nVAR p : Percent; b : BOOL; "
                      "END_VAR\nb := Split(high => p);\nEND_PROGRAM\n",
                  "value out of subrange in Main at line 9"},
        Violation{"InOutWrittenByTheCallee",
                  std::string(kPercent) +
                      "FUNCTION Bump : BOOL\nVAR_IN_OUT p : Percent; END_VAR\np := p + 60;\n"
                      "Bump := TRUE;\nEND_FUNCTION\nPROGRAM Main\nVAR p : Percent := 50; b : BOOL; "
                      "END_VAR\nb := Bump(p);\nEND_PROGRAM\n",
                  "value out of subrange in Bump at line 4"},
        Violation{"ForLoopPastTheRange",
                  main_with("k : INT(1..10); n : INT := 12; sum : INT;",
                            "FOR k := 1 TO n DO\n  sum := sum + k;\nEND_FOR;"),
                  "value out of subrange in Main at line 4"},
        Violation{"ForLoopStart",
                  main_with("k : INT(1..10); n : INT;", "FOR k := n TO 5 DO END_FOR;"),
                  "value out of subrange in Main at line 4"},
        Violation{"BitAssignment", main_with("p : Percent;", "p.7 := TRUE;"),
                  "value out of subrange in Main at line 4"}),
    [](const auto& c) { return c.param.name; });

TEST(Subrange, ForLoopRunsToTheUpperBoundAndKeepsTheLastValue) {
    StProgram run(main_with("k : INT(1..10); down : INT(1..10); sum : INT; n : INT := 10;",
                            "sum := 0;\nFOR k := 1 TO 10 DO sum := sum + k; END_FOR;\n"
                            "FOR down := n TO 1 BY -1 DO sum := sum + down; END_FOR;"));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(2));
    EXPECT_EQ(run.get<std::int16_t>("Main.sum"), 110);
    EXPECT_EQ(run.get<std::int16_t>("Main.k"), 10);
    EXPECT_EQ(run.get<std::int16_t>("Main.down"), 1);
}

TEST(Subrange, AResultOfTheSameSubrangeIsStoredWithoutACheckButArithmeticOnItIsChecked) {
    StProgram run(std::string(kPercent) + R"(
FUNCTION Full : Percent
  Full := 100;
END_FUNCTION
PROGRAM Main
VAR p : Percent; q : Percent := 1; END_VAR
p := Full();
q := Full() + Full();
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "value out of subrange in Main at line 9");
    EXPECT_EQ(run.get<std::int16_t>("Main.p"), 100);
    EXPECT_EQ(run.get<std::int16_t>("Main.q"), 1) << "q keeps its value";
}

TEST(Subrange, AVariableOfANarrowerSubrangeIsStoredWithoutACheck) {
    StProgram run(main_with("p : Percent; small : INT(20..30) := 25; out : INT;",
                            "p := small;\nout := p + small;"));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int16_t>("Main.out"), 50);
}

struct Refused {
    std::string name;
    std::string source;
    std::string message;
};

// A type is checked where it is used.
const std::string kUsesBad = "PROGRAM Main\nVAR b : Bad; END_VAR\nEND_PROGRAM\n";

class SubrangeRefused : public testing::TestWithParam<Refused> {};

TEST_P(SubrangeRefused, ReportsTheErrorWhereItIs) {
    const Refused& c = GetParam();
    StProgram run(c.source);
    EXPECT_FALSE(run.ok());
    EXPECT_NE(run.errors().find(c.message), std::string::npos) << run.errors();
}

INSTANTIATE_TEST_SUITE_P(
    Constants, SubrangeRefused,
    testing::Values(
        Refused{"AssignedConstant", main_with("p : Percent;", "p := 101;"),
                "test.st:4:6: error: the value 101 is outside Percent (0..100)"},
        Refused{"FoldedConstant", main_with("p : Percent;", "p := 50 * 3;"),
                "test.st:4:6: error: the value 150 is outside Percent (0..100)"},
        Refused{"NamedConstant",
                std::string(kPercent) + "PROGRAM Main\nVAR CONSTANT kMax : INT := 120; END_VAR\n"
                                        "VAR p : Percent; END_VAR\np := kMax;\nEND_PROGRAM\n",
                "test.st:5:6: error: the value 120 is outside Percent (0..100)"},
        Refused{"InitialValue", main_with("q : INT(10..20) := 5;", ""),
                "test.st:3:24: error: the value 5 is outside INT(10..20) (10..20)"},
        Refused{"ArgumentConstant",
                std::string(kPercent) +
                    "FUNCTION F : INT\nVAR_INPUT p : Percent; END_VAR\nF := p;\nEND_FUNCTION\n"
                    "PROGRAM Main\nVAR i : INT; END_VAR\ni := F(-1);\nEND_PROGRAM\n",
                "test.st:8:8: error: the value -1 is outside Percent (0..100)"},
        Refused{"EmptyRange", "TYPE Bad : INT (5..1); END_TYPE\n" + kUsesBad,
                "test.st:1:17: error: the subrange 5..1 is empty or does not fit in INT"},
        Refused{"BoundsOutsideTheBase", "TYPE Bad : SINT (0..200); END_TYPE\n" + kUsesBad,
                "the subrange 0..200 is empty or does not fit in SINT"},
        Refused{"NonIntegerBase", "TYPE Bad : REAL (0..1); END_TYPE\n" + kUsesBad,
                "a subrange needs an integer base type, not REAL"},
        Refused{"InOutNeedsTheSameSubrange",
                std::string(kPercent) +
                    "FUNCTION F : INT\nVAR_IN_OUT p : Percent; END_VAR\nF := p;\nEND_FUNCTION\n"
                    "PROGRAM Main\nVAR i : INT; END_VAR\ni := F(i);\nEND_PROGRAM\n",
                "VAR_IN_OUT 'p' needs a Percent variable"}),
    [](const auto& c) { return c.param.name; });

TEST(Subrange, InOutTakesAVariableOfTheSameBounds) {
    StProgram run(std::string(kPercent) +
                  "FUNCTION Bump : BOOL\nVAR_IN_OUT p : Percent; END_VAR\np := p + 1;\n"
                  "Bump := TRUE;\nEND_FUNCTION\nPROGRAM Main\nVAR v : INT(0..100); b : BOOL; "
                  "END_VAR\nb := Bump(v);\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(3));
    EXPECT_EQ(run.get<std::int16_t>("Main.v"), 3);
}

} // namespace
} // namespace eposp::compiler::test
