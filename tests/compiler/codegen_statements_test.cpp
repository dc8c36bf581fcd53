// Statements compiled and run (IEC 61131-3 ed. 3, 7.3.3): IF/ELSIF, CASE with ranges, lists
// and enumerations, FOR (with BY, EXIT, CONTINUE), WHILE, REPEAT, RETURN.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

struct StatementCase {
    std::string name;
    std::string declarations; // Main also has `x : DINT;`
    std::string body;
    std::int32_t expected; // of x
};

class StatementResult : public testing::TestWithParam<StatementCase> {};

TEST_P(StatementResult, GivesTheExpectedValue) {
    const StatementCase& c = GetParam();
    StProgram run("PROGRAM Main\nVAR x : DINT; " + c.declarations + " END_VAR\n" + c.body +
                  "\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Control, StatementResult,
    testing::Values(
        StatementCase{"IfTakesTheFirstTrueBranch", "a : INT := 5;",
                      "IF a < 3 THEN x := 1; ELSIF a < 10 THEN x := 2; ELSIF a < 20 THEN x := 3; "
                      "ELSE x := 4; END_IF;",
                      2},
        StatementCase{"IfElse", "a : INT := 50;",
                      "IF a < 3 THEN x := 1; ELSIF a < 10 THEN x := 2; ELSE x := 4; END_IF;", 4},
        StatementCase{"IfWithoutElse", "", "x := 7; IF x > 100 THEN x := 1; END_IF;", 7},
        StatementCase{"IfOrCondition", "a : BOOL; b : BOOL := TRUE;",
                      "IF a OR b THEN x := 1; END_IF;", 1},
        StatementCase{"IfNotAndCondition", "a : BOOL; b : BOOL := TRUE;",
                      "IF NOT a AND b THEN x := 1; END_IF;", 1},
        // Bit tests are one JTst / JNTst: both polarities, under NOT, literal on either side.
        StatementCase{"IfMaskedBitSet", "w : WORD := 16#8001;",
                      "IF (w AND 16#8000) <> 0 THEN x := 1; ELSE x := 2; END_IF;", 1},
        StatementCase{"IfMaskedBitClear", "w : WORD := 16#8001;",
                      "IF (w AND 16#0002) = 0 THEN x := 1; ELSE x := 2; END_IF;", 1},
        StatementCase{"IfNotMaskedBit", "w : DWORD := 16#10;",
                      "IF NOT (0 = (w AND 16#10)) THEN x := 1; ELSE x := 2; END_IF;", 1},
        StatementCase{"IfMaskedSignedWidened", "a : SINT := -128; b : INT := 16#100;",
                      "IF (a AND b) <> 0 THEN x := 1; ELSE x := 2; END_IF;", 1},
        StatementCase{"WhileMaskedBitCountsShifts", "w : LWORD := 16#80;",
                      "WHILE (w AND 1) = 0 DO w := SHR(w, 1); x := x + 1; END_WHILE;", 7},
        // A BOOL array element as the condition is one JtX / JfX.
        StatementCase{"IfBoolElement", "f : ARRAY[-1..1] OF BOOL := [FALSE, TRUE, FALSE]; i : INT;",
                      "FOR i := -1 TO 1 DO IF f[i] THEN x := x * 10 + 1; ELSE x := x * 10 + 2; "
                      "END_IF; END_FOR;",
                      212},
        StatementCase{"WhileNotBoolElement",
                      "f : ARRAY[0..9] OF BOOL := [FALSE, FALSE, FALSE, TRUE];",
                      "WHILE NOT f[x] DO x := x + 1; END_WHILE;", 3},
        StatementCase{"CaseValue", "s : INT := 2;",
                      "CASE s OF 1: x := 10; 2: x := 20; 3: x := 30; END_CASE;", 20},
        StatementCase{"CaseList", "s : INT := 7;",
                      "CASE s OF 1, 3, 5: x := 1; 2, 7: x := 2; END_CASE;", 2},
        StatementCase{"CaseRange", "s : DINT := 15;",
                      "CASE s OF 0..9: x := 1; 10..19: x := 2; ELSE x := 3; END_CASE;", 2},
        StatementCase{"CaseElse", "s : DINT := 99;",
                      "CASE s OF 0..9: x := 1; 10..19: x := 2; ELSE x := 3; END_CASE;", 3},
        StatementCase{"CaseNegativeLabel", "s : INT := -2;",
                      "CASE s OF -5..-1: x := 1; 0: x := 2; END_CASE;", 1},
        StatementCase{"ForSums", "i : INT;", "FOR i := 1 TO 10 DO x := x + i; END_FOR;", 55},
        StatementCase{"ForBy", "i : INT;", "FOR i := 0 TO 10 BY 3 DO x := x + i; END_FOR;", 18},
        StatementCase{"ForDownwards", "i : INT;",
                      "FOR i := 10 TO 1 BY -2 DO x := x * 10 + i; END_FOR;",
                      ((((10 * 10) + 8) * 10 + 6) * 10 + 4) * 10 + 2},
        StatementCase{"ForComputedStep", "i, s : INT := 2;",
                      "FOR i := 0 TO 10 BY s DO x := x + i; END_FOR;", 30},
        StatementCase{"ForComputedNegativeStep", "i : INT; s : INT := -3;",
                      "FOR i := 9 TO 1 BY s DO x := x * 10 + i; END_FOR;", 963},
        StatementCase{"ForEmpty", "i : INT;", "FOR i := 5 TO 1 DO x := x + 1; END_FOR;", 0},
        StatementCase{"ForVariableAfterLoop", "i : INT;", "FOR i := 1 TO 3 DO END_FOR; x := i;", 4},
        StatementCase{"ForExit", "i : INT;",
                      "FOR i := 1 TO 100 DO IF i > 5 THEN EXIT; END_IF; x := x + 1; END_FOR;", 5},
        StatementCase{"ForContinue", "i : INT;",
                      "FOR i := 1 TO 10 DO IF i MOD 2 = 0 THEN CONTINUE; END_IF; x := x + i; "
                      "END_FOR;",
                      25},
        StatementCase{"NestedExitLeavesInnerLoop", "i, j : INT;",
                      "FOR i := 1 TO 3 DO FOR j := 1 TO 3 DO IF j = 2 THEN EXIT; END_IF; "
                      "x := x + 1; END_FOR; END_FOR;",
                      3},
        StatementCase{"While", "", "WHILE x < 100 DO x := x * 2 + 1; END_WHILE;", 127},
        StatementCase{"WhileNeverEntered", "", "WHILE x > 0 DO x := 5; END_WHILE;", 0},
        StatementCase{"Repeat", "", "REPEAT x := x + 3; UNTIL x > 10 END_REPEAT;", 12},
        StatementCase{"RepeatRunsOnce", "", "REPEAT x := x + 1; UNTIL TRUE END_REPEAT;", 1},
        StatementCase{"Return", "", "x := 1; RETURN; x := 2;", 1}),
    [](const auto& c) { return c.param.name; });

TEST(CaseStatement, EnumerationLabels) {
    StProgram run(R"(
TYPE Mode : (Off, Slow, Fast); END_TYPE
PROGRAM Main
VAR m : Mode := Fast; x : DINT; END_VAR
CASE m OF
  Off: x := 0;
  Slow, Fast: x := 2;
END_CASE;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), 2);
}

} // namespace
} // namespace eposp::compiler::test
