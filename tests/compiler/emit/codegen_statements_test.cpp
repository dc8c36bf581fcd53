// Statements compiled and run (IEC 61131-3 ed. 3, 7.3.3): IF/ELSIF, CASE with ranges, lists
// and enumerations, FOR (with BY, EXIT, CONTINUE), WHILE, REPEAT, RETURN.
#include "codegen_harness.hpp"

#include <algorithm>
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
        // A label range spanning all of LINT (its width does not fit 64 bits signed).
        StatementCase{"CaseOverTheWholeOfLint", "l : LINT := 5;",
                      "CASE l OF -9223372036854775807..9223372036854775807: x := 1; END_CASE;", 1},
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
        // A loop up to the end of its type ends there, the variable wrapped (it never ended).
        StatementCase{"ForUpToTheTopOfUsint", "u : USINT;",
                      "FOR u := 250 TO 255 DO x := x + 1; END_FOR; x := x * 1000 + u;", 6000},
        StatementCase{"ForUpToTheTopOfIntBy3", "i : INT;",
                      "FOR i := 32760 TO 32767 BY 3 DO x := x + 1; END_FOR; x := x * 100000 + i;",
                      300000 - 32767},
        StatementCase{"ForUpToTheTopOfDint", "d : DINT;",
                      "FOR d := 2147483640 TO 2147483647 DO x := x + 1; END_FOR;", 8},
        StatementCase{"ForDownToTheBottomOfSint", "s : SINT;",
                      "FOR s := -120 TO -128 BY -4 DO x := x + 1; END_FOR; x := x * 1000 + s;",
                      3124},
        StatementCase{"ForDownToTheBottomOfLint", "l : LINT;",
                      "FOR l := -9223372036854775800 TO -9223372036854775807 - 1 BY -1 DO "
                      "x := x + 1; END_FOR;",
                      9},
        StatementCase{"ForUpToTheTopOfUlintBy5", "u : ULINT;",
                      "FOR u := 18446744073709551610 TO 18446744073709551615 BY 5 DO x := x + 1; "
                      "END_FOR; x := x * 1000 + ULINT_TO_DINT(u);",
                      2004},
        StatementCase{"ForComputedStepUpToTheTopOfInt", "i : INT; s : INT := 7;",
                      "FOR i := 32700 TO 32767 BY s DO x := x + 1; END_FOR;", 10},
        StatementCase{"ForComputedStepDownToTheBottomOfInt", "i : INT; s : INT := -7;",
                      "FOR i := -32700 TO -32768 BY s DO x := x + 1; END_FOR;", 10},
        StatementCase{"ForSubrangeUpToTheTopOfItsType", "t : USINT(250..255);",
                      "FOR t := 250 TO 255 DO x := x + 1; END_FOR; x := x * 1000 + t;", 6255},
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

TEST(Enumerations, StartAtTheirFirstValueWhateverItsNumber) {
    // 6.4.4.2: without an initial value an enumerated variable holds the first enumerator, in
    // variables, structure members and FB inputs left out of a call alike.
    StProgram run(R"(
TYPE Direction : (Up := 1, Down, Sideways := 7); END_TYPE
TYPE Holder : STRUCT d : Direction; END_STRUCT; END_TYPE
FUNCTION_BLOCK Fb
  VAR_INPUT d : Direction; END_VAR
  VAR_OUTPUT x : BOOL; END_VAR
  x := d = Up;
END_FUNCTION_BLOCK
PROGRAM Main
VAR v : Direction; h : Holder; f : Fb; a, b, c : BOOL; END_VAR
a := v = Up;
b := h.d = Up;
f();
c := f.x;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_TRUE(run.get<bool>("Main.a"));
    EXPECT_TRUE(run.get<bool>("Main.b"));
    EXPECT_TRUE(run.get<bool>("Main.c"));
}

TEST(CaseStatement, EnumeratorsNamedLikeStandardFunctions) {
    // MOVE, SEL and LIMIT are standard functions; where a value is wanted they are the
    // enumerators, and called they are still the functions.
    StProgram run(R"(
TYPE Step : (Idle, Load, Move, Sel, Limit); END_TYPE
PROGRAM Main
VAR s : Step; trail, n : DINT; moving : BOOL; END_VAR
CASE s OF
  Idle: s := Load; trail := trail * 10 + 1;
  Load: s := Move; trail := trail * 10 + 2;
  Move: s := Step#Sel; trail := trail * 10 + 3;
  Sel: s := Limit;
  Limit: s := Idle;
END_CASE;
moving := s = Move OR Sel <> s;
n := MOVE(LIMIT(0, SEL(moving, 1, 2), 5));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(3)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.trail"), 123);
    EXPECT_FALSE(run.get<bool>("Main.moving")) << "s is Sel";
    EXPECT_EQ(run.get<std::int32_t>("Main.n"), 1);
}

struct CaseDispatch {
    std::string name;
    std::string selector_type;
    std::string first;  // the first selector value tried
    std::string labels; // the branches, each setting `code`
    std::int64_t expected;
    bool table; // whether the labels are dense enough for a jump table
};

class CaseDispatchTest : public testing::TestWithParam<CaseDispatch> {};

// Every selector value of a window around the labels goes to its branch (or ELSE), whether the
// CASE compiles to a jump table or to compares: the digits of `trail` record the path taken.
TEST_P(CaseDispatchTest, EverySelectorReachesItsBranch) {
    const CaseDispatch& c = GetParam();
    StProgram run("PROGRAM Main\nVAR s : " + c.selector_type + "; k, code : INT; trail : LINT; " +
                  "END_VAR\ns := " + c.first + ";\nFOR k := 1 TO 12 DO\n  CASE s OF " + c.labels +
                  " ELSE code := 9; END_CASE;\n  trail := trail * 10 + code;\n  s := s + 1;\n" +
                  "END_FOR;\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    const vm::Image& image = run.image();
    const bool has_table = std::any_of(image.code.begin(), image.code.end(), [](const auto& ins) {
        return vm::opcode_info(ins.opcode).name.starts_with("JTab");
    });
    EXPECT_EQ(has_table, c.table);
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int64_t>("Main.trail"), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Labels, CaseDispatchTest,
    testing::Values(
        CaseDispatch{"DenseIntWithRangesAndLists", "INT", "-2",
                     "0: code := 1; 1, 3: code := 2; 4..6: code := 3; 2: code := 4;",
                     991'242'333'999, true},
        CaseDispatch{"NegativeDint", "DINT", "-8",
                     "-6: code := 1; -5..-4: code := 2; -3: code := 3; 0: code := 4;",
                     991'223'994'999, true},
        CaseDispatch{"UintAtTheTopOfItsRange", "UINT", "65530",
                     "65531: code := 1; 65532..65534: code := 2; 65535: code := 3; 0: code := 4;",
                     912'223'499'999, false},
        CaseDispatch{"UintDense", "UINT", "65526",
                     "65531: code := 1; 65532..65534: code := 2; 65535: code := 3;",
                     999'991'222'399, true},
        CaseDispatch{"UdintWrapsPastItsTop", "UDINT", "4294967290",
                     "4294967291: code := 1; 4294967292..4294967294: code := 2; "
                     "4294967295: code := 3;",
                     912'223'999'999, true},
        CaseDispatch{"SparseLabelsCompare", "DINT", "0",
                     "1: code := 1; 5: code := 2; 1000: code := 3; 100000: code := 4;",
                     919'992'999'999, false}),
    [](const auto& param_info) { return param_info.param.name; });

TEST(CaseStatement, DenseEnumerationUsesATable) {
    StProgram run(R"(
TYPE Step : (Idle, Load, Travel, Unload, Fault); END_TYPE
PROGRAM Main
VAR s : Step; visits : ARRAY[0..4] OF INT; k : INT; END_VAR
FOR k := 1 TO 7 DO
  CASE s OF
    Idle: visits[0] := visits[0] + 1; s := Load;
    Load: visits[1] := visits[1] + 1; s := Travel;
    Travel: visits[2] := visits[2] + 1; s := Unload;
    Unload: visits[3] := visits[3] + 1; s := Fault;
    Fault: visits[4] := visits[4] + 1; s := Idle;
  END_CASE;
END_FOR;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_TRUE(std::any_of(run.image().code.begin(), run.image().code.end(),
                            [](const auto& ins) { return ins.opcode == vm::Opcode::JTabI16; }));
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.visits[0]"), 2);
    EXPECT_EQ(run.get<std::int16_t>("Main.visits[1]"), 2);
    EXPECT_EQ(run.get<std::int16_t>("Main.visits[4]"), 1);
}

} // namespace
} // namespace eposp::compiler::test
