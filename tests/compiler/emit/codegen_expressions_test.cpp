// Expressions compiled and run: operators with IEC precedence, wrap-around, conversions,
// implicit widening, selection and numeric standard functions, enumerations, arrays,
// structures and references. Each case is a PROGRAM Main run for one scan.
#include "codegen_harness.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

struct IntCase {
    std::string name;
    std::string declarations; // inside VAR ... END_VAR of Main, which also has `x : LINT;`
    std::string body;
    std::int64_t expected; // of x
};

class IntegerResult : public testing::TestWithParam<IntCase> {};

TEST_P(IntegerResult, GivesTheExpectedValue) {
    const IntCase& c = GetParam();
    StProgram run(
        "TYPE Pair : STRUCT a, b : INT; END_STRUCT; END_TYPE\nPROGRAM Main\nVAR x : LINT; " +
        c.declarations + " END_VAR\n" + c.body + "\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int64_t>("Main.x"), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Operators, IntegerResult,
    testing::Values(
        IntCase{"MultiplicationBindsTighter", "", "x := 2 + 3 * 4;", 14},
        IntCase{"Parentheses", "", "x := (2 + 3) * 4;", 20},
        IntCase{"SubtractionIsLeftAssociative", "", "x := 10 - 3 - 2;", 5},
        IntCase{"DivisionTruncates", "", "x := -7 / 2;", -3},
        IntCase{"ModTakesTheDividendsSign", "", "x := -7 MOD 3;", -1},
        IntCase{"UnaryMinusOfVariable", "d : DINT := 5;", "x := -d;", -5},
        IntCase{"IntOverflowWraps", "i : INT := 32767;", "i := i + 1; x := i;", -32768},
        IntCase{"SintOverflowWraps", "s : SINT := 127;", "s := s + 1; x := s;", -128},
        IntCase{"UsintUnderflowWraps", "u : USINT;", "u := u - 1; x := u;", 255},
        IntCase{"DintMultiplyWraps", "d : DINT := 65536;", "d := d * d; x := d;", 0},
        IntCase{"NestedIntArithmeticDoesNotOverflowBeforeMod", "a, b : INT := 300;",
                "x := (a * b) MOD 1000;", 0},
        IntCase{"IntWidensToLint", "i : INT := -3;", "x := i;", -3},
        // AND, OR and XOR of INTs give an INT, as the typing stage types them, even where an
        // operand is computed in DINT: i * 2 is cut to 16#FFFE first, so the OR is 16#FFFF, -1.
        IntCase{"BitOperatorOfIntsIsAnInt", "i : INT := 16#7FFF;", "x := i OR i * 2;", -1},
        IntCase{"BitOperatorOfIntsIsAnIntInsideAnExpression", "i : INT := 16#7FFF;",
                "x := (i OR i * 2) + 1;", 0},
        IntCase{"PowerIsLreal", "", "x := LREAL_TO_LINT(2 ** 10);", 1024},
        IntCase{"BitAnd", "w : WORD := 16#F0F0;", "w := w AND 16#FF00; x := WORD_TO_LINT(w);",
                0xF000},
        IntCase{"BitOrXorNot", "w : WORD := 16#00F0;",
                "w := (w OR 16#0F00) XOR 16#0FF0; x := WORD_TO_LINT(NOT w);", 0xFFFF},
        IntCase{"ShiftLeft", "b : BYTE := 16#81;", "x := BYTE_TO_LINT(SHL(b, 1));", 0x02},
        IntCase{"ShiftRight", "d : DWORD := 16#80000000;", "x := DWORD_TO_LINT(SHR(d, 31));", 1},
        IntCase{"RotateLeft", "b : BYTE := 16#81;", "x := BYTE_TO_LINT(ROL(b, 1));", 0x03},
        IntCase{"RotateRight", "b : BYTE := 16#81;", "x := BYTE_TO_LINT(ROR(b, 1));", 0xC0},
        IntCase{"BooleanOperators", "b : BOOL;",
                "b := (3 < 4) AND NOT (2 = 3) AND (1 <> 2 XOR FALSE); x := BOOL_TO_LINT(b);", 1},
        IntCase{"RealToIntRoundsTiesToEven", "", "x := REAL_TO_INT(2.5);", 2},
        IntCase{"NegativeRealRounds", "", "x := LREAL_TO_DINT(-2.5);", -2},
        IntCase{"TruncTowardZero", "", "x := TRUNC(-2.7);", -2},
        IntCase{"NarrowingConversionWraps", "", "x := DINT_TO_SINT(300);", 44},
        IntCase{"TimeToDintInMilliseconds", "", "x := TIME_TO_DINT(T#1s500ms);", 1500},
        IntCase{"DintToTime", "t : TIME;", "t := DINT_TO_TIME(250); x := TIME_TO_LINT(t);", 250},
        IntCase{"TimeArithmetic", "t : TIME := T#1s;",
                "t := t + T#500ms - T#250ms; x := TIME_TO_DINT(t);", 1250},
        IntCase{"TimeTimesNumber", "t : TIME := T#1s;",
                "t := t * 3 / 2; t := t * 0.5; x := TIME_TO_DINT(t);", 750},
        IntCase{"TimeOfDayWrapsAroundMidnight", "t : TOD := TOD#23:00:00;",
                "t := t + T#2h; x := TOD_TO_DINT(t);", 3600000},
        IntCase{"CharLiterals", "c : CHAR := CHAR#'A'; w : WCHAR;",
                "w := WCHAR#\"$0100\"; c := CHAR#'$42';"
                "x := BYTE_TO_LINT(CHAR_TO_BYTE(c)) * 1000 + WORD_TO_LINT(WCHAR_TO_WORD(w));",
                66'256},
        // The named functions of table 30, in milliseconds (TIME) or seconds (DT).
        IntCase{"AddTime", "", "x := TIME_TO_LINT(ADD_TIME(T#1s, T#500ms));", 1500},
        IntCase{"SubTimeWithNamedInputs", "",
                "x := TIME_TO_LINT(SUB_TIME(IN2 := T#250ms, IN1 := T#1s));", 750},
        IntCase{"MulTimeByAnInteger", "", "x := TIME_TO_LINT(MUL_TIME(T#1s, 3));", 3000},
        IntCase{"DivTimeByAReal", "", "x := TIME_TO_LINT(DIV_TIME(T#1s, 2.5));", 400},
        IntCase{"AddTodTimeWrapsAroundMidnight", "",
                "x := TOD_TO_LINT(ADD_TOD_TIME(TOD#23:59:59, T#2s));", 1000},
        IntCase{"SubTodTod", "", "x := TIME_TO_LINT(SUB_TOD_TOD(TOD#12:00:01, TOD#12:00:00));",
                1000},
        IntCase{"SubDateDate", "", "x := TIME_TO_LINT(SUB_DATE_DATE(D#2024-03-01, D#2024-02-28));",
                2 * 86'400'000},
        IntCase{"ConcatDateTodThenSubDtDt", "d : DT;",
                "d := CONCAT_DATE_TOD(D#2024-01-31, TOD#12:00:00);"
                "x := TIME_TO_LINT(SUB_DT_DT(d, DT#2024-01-31-11:00:00));",
                3'600'000},
        IntCase{"AddAndSubDtTime", "d : DT := DT#2024-01-31-12:00:00;",
                "x := TIME_TO_LINT(SUB_DT_DT(ADD_DT_TIME(d, T#1h), SUB_DT_TIME(d, T#1h)));",
                7'200'000},
        IntCase{"ReusedElementIsNotOverwritten", "a : ARRAY[0..1] OF DINT := [5, 1]; j : INT;",
                "x := a[j] + MAX(a[j], 30) + a[j + 1]; a[j] := a[j + 1]; x := x + a[j] * 100;",
                136},
        IntCase{"IndexChangesBetweenStatements",
                "a : ARRAY[0..3] OF DINT := [10, 20, 30, 40]; i : INT := 1;",
                "x := a[i]; i := i + 1; x := x + a[i]; a[i] := 1; x := x + a[i];", 51},
        IntCase{"ElementChangedThroughReference",
                "a : ARRAY[0..3] OF DINT := [10, 20, 30, 40]; p : REF_TO DINT; i : INT := 1;",
                "x := a[i]; p := REF(a[1]); p^ := 7; x := x + a[i];", 27},
        IntCase{"LoopReadsEachElement", "a : ARRAY[0..3] OF DINT := [10, 20, 30, 40]; i : INT;",
                "FOR i := 0 TO 3 DO x := x + a[i] + a[i]; END_FOR;", 200},
        IntCase{"ElementAddressAfterIndexChange", "s : ARRAY[0..2] OF Pair; i : INT;",
                "s[i].b := 3; i := i + 1; s[i].b := 4; x := s[0].b * 10 + s[1].b;", 34},
        IntCase{"Max", "", "x := MAX(3, 7, 5);", 7},
        IntCase{"Min", "a : INT := 4;", "x := MIN(a, 9, -2);", -2},
        IntCase{"LimitAbove", "", "x := LIMIT(0, 15, 10);", 10},
        IntCase{"LimitBelow", "", "x := LIMIT(0, -15, 10);", 0},
        IntCase{"LimitInside", "", "x := LIMIT(0, 5, 10);", 5},
        IntCase{"LimitFormalAnyOrder", "", "x := LIMIT(IN := 15, MX := 10, MN := 0);", 10},
        IntCase{"SubFormalAnyOrder", "", "x := SUB(IN2 := 1, IN1 := 10);", 9},
        IntCase{"MuxFormal", "", "x := MUX(IN1 := 20, K := 1, IN0 := 10);", 20},
        IntCase{"MidFormal", "s : STRING := 'abcdef';",
                "x := LEN(IN := MID(P := 2, IN := s, L := 3));", 3},
        IntCase{"Sel", "", "x := SEL(TRUE, 1, 2);", 2},
        IntCase{"Mux", "k : INT := 2;", "x := MUX(k, 10, 20, 30);", 30},
        IntCase{"Abs", "d : DINT := -5;", "x := ABS(d);", 5},
        IntCase{"Sqrt", "", "x := LREAL_TO_LINT(SQRT(16.0));", 4},
        // An untyped literal that does not fit the other operand's type makes the operation
        // wider, as the typing stage types it (was computed and cut in SINT and INT).
        IntCase{"LiteralBeyondASmallIntegerWidensTheOperation", "s : SINT := 1;", "x := s + 200;",
                201},
        IntCase{"LiteralBeyondAnIntWidensTheOperation", "i : INT := 1;", "x := i + 100000;",
                100001},
        // The inputs' common type, LREAL, as the typing stage gives it (was computed in REAL).
        IntCase{"Atan2OfARealAndAnLrealIsAnLreal", "y : REAL := 1.0; t : LREAL := 3.0;",
                "x := BOOL_TO_LINT(ATAN2(y, t) = ATAN2(REAL_TO_LREAL(y), t));", 1},
        IntCase{"ExtensibleComparison", "", "x := BOOL_TO_LINT(GT(5, 4, 3) AND NOT GT(5, 6, 3));",
                1},
        IntCase{"AddFunction", "", "x := ADD(1, 2, 3, 4);", 10},
        // An input of ADD, GT, ... stores its argument (docs/st-language.md): INT a * b is cut
        // to INT, 90000 to 24464, before the function computes on INTs (ADD failed to compile,
        // GT compared 90000).
        IntCase{"AddOfAnIntProductIsAnInt", "a, b : INT := 300; c : INT := 1; i : INT;",
                "i := ADD(a * b, c); x := i;", 24465},
        IntCase{"ComparisonFunctionCutsAnIntProduct", "a, b : INT := 300; c : INT := 25000;",
                "x := BOOL_TO_LINT(GT(a * b, c));", 0},
        // The operator keeps a product of INTs in DINT as an operand (CODESYS).
        IntCase{"ComparisonOperatorKeepsAnIntProductInDint", "a, b : INT := 300; c : INT := 25000;",
                "x := BOOL_TO_LINT(a * b > c);", 1},
        // So is a negation of INTs: -(-32768) is 32768 inside an expression, cut where stored.
        IntCase{"NegationOfAnIntIsComputedInDint", "i : INT := -32768;",
                "x := BOOL_TO_LINT(-i > 0);", 1},
        IntCase{"NegationOfAUsintIsComputedInDint", "u : USINT := 5;", "x := BOOL_TO_LINT(-u < 0);",
                1},
        IntCase{"NegationOfAnIntProductIsComputedInDint", "a, b : INT := 300;",
                "x := BOOL_TO_LINT(-(a * b) < -30000);", 1},
        IntCase{"NegationHeldInDintFeedsArithmetic", "i : INT := -32768;", "x := (-i + 1) / 2;",
                16384},
        IntCase{"StoredNegationIsCutToItsType", "i : INT := -32768; d : DINT;", "d := -i; x := d;",
                -32768},
        IntCase{"Move", "", "x := MOVE(42);", 42},
        IntCase{"ArrayElement", "a : ARRAY[1..5] OF INT := [1, 2(7), 3];", "x := a[3] + a[4];", 10},
        IntCase{"ArrayIndexedByVariable",
                "a : ARRAY[1..5] OF INT := [1, 2, 3, 4, 5]; i : INT := 5;",
                "a[i] := 50; x := a[i] + a[1];", 51},
        // A constant next to a DINT index moves into the bound instead of costing an addition.
        IntCase{"NeighbourElementsOfADintIndex",
                "a : ARRAY[1..5] OF DINT := [1, 2, 3, 4, 5]; j : DINT := 3;",
                "x := a[j - 1] * 100 + a[j] * 10 + a[1 + j]; a[j + 2] := 9; x := x * 10 + a[5];",
                2349},
        IntCase{"DisplacedIndexWrapsLikeTheSum",
                "a : ARRAY[-2147483648..-2147483647] OF DINT := [7, 8]; j : DINT := 2147483647;",
                "x := a[j + 1] * 10 + a[j + 2];", 78},
        IntCase{"NegativeIntIndex", "a : ARRAY[-3..-1] OF SINT := [1, 2, 3]; i : INT := -2;",
                "x := a[i] * 10 + a[i - 1];", 21},
        IntCase{"UdintIndex", "a : ARRAY[0..3] OF DINT := [1, 2, 3, 4]; u : UDINT := 3;",
                "x := a[u];", 4},
        IntCase{"TwoDimensionalArray", "m : ARRAY[0..2, 1..3] OF DINT; i, j : INT;",
                "FOR i := 0 TO 2 DO FOR j := 1 TO 3 DO m[i, j] := i * 10 + j; END_FOR; END_FOR;"
                "i := 2; j := 3; x := m[i, j] + m[1, 2];",
                35},
        IntCase{"Reference", "d : DINT; p : REF_TO DINT;", "p := REF(d); p^ := 5; x := d + p^;",
                10},
        IntCase{"NullReferenceCompares", "p : REF_TO DINT;", "IF p = NULL THEN x := 1; END_IF;", 1},
        IntCase{"BitRead", "w : WORD := 16#0008; b : BOOL;", "b := w.3; x := BOOL_TO_LINT(b);", 1},
        IntCase{"BitWrite", "w : WORD := 16#00FF;",
                "w.0 := FALSE; w.15 := TRUE; x := WORD_TO_LINT(w);", 0x80FE},
        IntCase{"Sizeof", "a : ARRAY[1..10] OF DINT;", "x := SIZEOF(a) + SIZEOF(x);", 48},
        IntCase{"Adr", "d : DINT; p : POINTER TO DINT;", "p := ADR(d); p^ := 9; x := d;", 9},
        // CODESYS: SIZEOF is a constant of the smallest unsigned type holding it, and ADR is an
        // address for a POINTER TO of any type (OSCAT passes ADR(buf), SIZEOF(buf) this way).
        IntCase{"SizeofFitsAUint", "a : ARRAY[1..10] OF DINT; u : UINT; i : INT;",
                "u := SIZEOF(a); i := SIZEOF(a); x := UINT_TO_LINT(u) + i;", 80},
        IntCase{"SizeofOfALargeArrayIsAUdint", "a : ARRAY[1..20000] OF DINT; u : UDINT;",
                "u := SIZEOF(a); x := u;", 80000},
        // Bit strings count as unsigned integers of their width in arithmetic (CODESYS).
        IntCase{"BitStringArithmeticWrapsUnsigned",
                "d : DWORD := 16#FFFF_FFFE; w : WORD := 7; b : BYTE := 200;",
                "d := d + d / 2 + 5; w := w * w MOD 10; b := b + b;"
                "x := DWORD_TO_LINT(d) * 1000 + WORD_TO_LINT(w) * 100 + BYTE_TO_LINT(b);",
                2'147'483'650'000LL + 900 + 144},
        // CODESYS pointer arithmetic counts bytes.
        IntCase{"PointerArithmetic",
                "a : ARRAY[0..3] OF INT := [1, 2, 3, 4]; p : POINTER TO INT; k : DINT := 4;",
                "p := ADR(a); p := p + 2; x := p^; p := p + k; x := x * 10 + p^;"
                "p := p - 2; x := x * 10 + p^;",
                243},
        IntCase{"AdrIntoAPointerToAnotherArrayType",
                "a : ARRAY[0..3] OF INT := [1, 2, 3, 4]; p : POINTER TO ARRAY[0..1000] OF INT;",
                "p := ADR(a); x := p^[3] * 10 + p^[0];", 41},
        IntCase{"UnsignedCompare", "u : UDINT := 16#FFFFFFFF;", "IF u > 1 THEN x := 1; END_IF;",
                1}),
    [](const auto& c) { return c.param.name; });

TEST(StructsAndEnums, ArraysOfStructuresAndEnumerationsRun) {
    StProgram run(R"(
TYPE
  Color : (Red, Green := 5, Blue);
  Point : STRUCT x : DINT := 1; y : DINT; c : Color := Blue; END_STRUCT;
END_TYPE
PROGRAM Main
VAR
  pts : ARRAY[0..3] OF Point;
  p : Point := (y := 7);
  i : INT;
  sum : DINT;
  c : Color;
  n : INT;
END_VAR
FOR i := 0 TO 3 DO pts[i].y := INT_TO_DINT(i) * 2; END_FOR;
pts[2] := p;
sum := 0;
FOR i := 0 TO 3 DO sum := sum + pts[i].x + pts[i].y; END_FOR;
c := Color#Green;
IF c = Green AND pts[0].c = Blue THEN n := 6; END_IF;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    // x: 4 * 1; y: 0 + 2 + 7 + 6.
    EXPECT_EQ(run.get<std::int32_t>("Main.sum"), 4 + 15);
    EXPECT_EQ(run.get<std::int16_t>("Main.c"), 5);
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 6);
    EXPECT_EQ(run.get<std::int16_t>("Main.pts[3].c"), 6);
}

// Parts of array elements are reached in one indexed access, whatever their depth and kind.
TEST(StructsAndEnums, PartsOfArrayElementsAtEveryDepth) {
    StProgram run(R"(
TYPE
  Inner : STRUCT lo, hi : INT; END_STRUCT;
  Station : STRUCT id : SINT; name : STRING[8]; limits : Inner; samples : ARRAY[1..3] OF DINT; active : BOOL; END_STRUCT;
END_TYPE
PROGRAM Main
VAR
  st : ARRAY[0..2] OF Station;
  copy : Station;
  i : INT := 1;
  j : DINT := 2;
  total : DINT;
  label : STRING[20];
  flagged : INT;
END_VAR
st[i].id := 7;
st[i].name := 'press';
st[i].limits.hi := 300;
st[i].samples[j] := 40;
st[i].samples[j + 1] := 2;
st[i].active := TRUE;
copy := st[i];
st[0] := copy;
st[0].limits.lo := -5;
total := SINT_TO_DINT(st[0].id) + INT_TO_DINT(st[0].limits.hi + st[0].limits.lo) + st[0].samples[2] + st[i].samples[3];
label := CONCAT(st[i].name, '/', st[0].name);
FOR i := 0 TO 2 DO IF st[i].active THEN flagged := flagged + 1; END_IF; END_FOR;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.total"), 7 + 295 + 40 + 2);
    EXPECT_EQ(run.get_string("Main.label"), "press/press");
    EXPECT_EQ(run.get<std::int16_t>("Main.flagged"), 2);
    EXPECT_EQ(run.get<std::int16_t>("Main.st[1].limits.lo"), 0);
}

TEST(Reals, ArithmeticAndFunctions) {
    StProgram run(R"(
PROGRAM Main
VAR a : REAL := 1.5; b : LREAL; c : LREAL; i : INT := 3; third : LREAL := -1.0 / 3.0 * 2; END_VAR
b := a * 2.0 + i;
c := SIN(0.0) + EXPT(2.0, 3.0) + ABS(-1.25);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_DOUBLE_EQ(run.get<double>("Main.b"), 6.0);
    EXPECT_DOUBLE_EQ(run.get<double>("Main.c"), 9.25);
    EXPECT_DOUBLE_EQ(run.get<double>("Main.third"), -1.0 / 3.0 * 2);
}

// `**` is EXPT (table 24): on a REAL base a REAL, as the typing stage types it (was computed
// in LREAL, and storing it into a REAL failed to compile).
TEST(Reals, PowerOfARealIsAReal) {
    StProgram run(R"(
PROGRAM Main
VAR r : REAL := 3.0; q : REAL; x : LREAL; END_VAR
q := r ** 2.0;
x := r ** 0.5;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<float>("Main.q"), 9.0F);
    EXPECT_EQ(run.get<double>("Main.x"), static_cast<double>(std::pow(3.0F, 0.5F)));
}

// Ed. 3, 6.5.4: a POU's own constants size its arrays and strings.
TEST(Constants, OfThePouSizeItsArraysAndStrings) {
    StProgram run("PROGRAM Main\nVAR CONSTANT kLast : INT := 3; kText : INT := 2; END_VAR\n"
                  "VAR a : ARRAY[0..kLast] OF INT; s : STRING[kText]; n : DINT; END_VAR\n"
                  "a[kLast] := 7; s := 'abc'; n := SIZEOF(a);\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.a[3]"), 7);
    EXPECT_EQ(run.get<std::int32_t>("Main.n"), 8);
    EXPECT_EQ(run.get_string("Main.s"), "ab");
}

} // namespace
} // namespace eposp::compiler::test
