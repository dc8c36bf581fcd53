// The reference evaluator on hand-written programs whose results are worked out from
// IEC 61131-3 ed. 3 and docs/st-language.md, not by running the VM.

#include "eposp/reference/reference_program.hpp"

#include <bit>
#include <gtest/gtest.h>

namespace eposp::reference {
namespace {

/// Runs `body` in `PROGRAM Main` with `declarations` for `scans` scans.
ReferenceProgram run(const std::string& declarations, const std::string& body, int scans = 1) {
    ReferenceProgram program("PROGRAM Main\nVAR\n" + declarations + "\nEND_VAR\n" + body +
                             "\nEND_PROGRAM\n");
    EXPECT_TRUE(program.ok()) << program.errors();
    if (program.ok()) {
        EXPECT_TRUE(program.scans(scans)) << program.fault();
    }
    return program;
}

std::int64_t as_signed(const ReferenceProgram& program, const std::string& path, int bits) {
    const std::uint64_t raw = program.bits(path).value();
    const int shift = 64 - bits;
    return static_cast<std::int64_t>(raw << shift) >> shift;
}

TEST(ReferenceEvaluator, IntegersWrapAtTheirWidthWhereStored) {
    const auto p = run("s : SINT := 127; us : USINT := 255; d : DINT := 2147483647; "
                       "ud : UDINT; a, b : INT := 300; c : INT := 100; i : INT;",
                       "s := s + 1; us := us + 1; d := d + 1; ud := ud - 1; i := a * b / c;");
    EXPECT_EQ(as_signed(p, "Main.s", 8), -128);
    EXPECT_EQ(p.bits("Main.us"), 0u);
    EXPECT_EQ(as_signed(p, "Main.d", 32), -2147483648LL);
    EXPECT_EQ(p.bits("Main.ud"), 4294967295u);
    // INT operands are computed in DINT inside the expression: 90000 / 100, not a wrapped product.
    EXPECT_EQ(as_signed(p, "Main.i", 16), 900);
}

TEST(ReferenceEvaluator, AFunctionsInputIsCutToItsTypeLikeAnyStoredValue) {
    const auto p = run("a, b : INT := 20000; m : INT; d : DINT;",
                       "m := MAX(a + b, 5); d := INT_TO_DINT(a + b);");
    EXPECT_EQ(as_signed(p, "Main.m", 16), 5); // 40000 is -25536 as an INT
    EXPECT_EQ(as_signed(p, "Main.d", 32), -25536);
}

TEST(ReferenceEvaluator, NarrowingThenWideningConversionsZeroExtend) {
    const auto p =
        run("d : DINT := -1; ud : UDINT; l, m, n : LINT; u : ULINT; r : LREAL;",
            "ud := DINT_TO_UDINT(d); l := UDINT_TO_LINT(ud);"
            "u := DWORD_TO_ULINT(ULINT_TO_DWORD(16#FFFFFFFFFFFFFFFE));"
            "r := UDINT_TO_LREAL(DINT_TO_UDINT(-32768));"
            "m := DWORD_TO_LINT(SINT_TO_DWORD(-2)); n := UDINT_TO_LINT(LINT_TO_UDINT(-1));");
    EXPECT_EQ(p.bits("Main.l"), 4294967295u);
    EXPECT_EQ(p.bits("Main.u"), 4294967294u);
    EXPECT_EQ(p.bits("Main.r"), std::bit_cast<std::uint64_t>(4294934528.0));
    EXPECT_EQ(p.bits("Main.m"), 4294967294u);
    EXPECT_EQ(p.bits("Main.n"), 4294967295u);
}

TEST(ReferenceEvaluator, RealToIntegerRoundsToNearestTiesToEven) {
    const auto p = run("a, b, c, d : INT; e : DINT; t : DINT; x : REAL := 2.5;",
                       "a := REAL_TO_INT(x); b := REAL_TO_INT(-0.5); c := REAL_TO_INT(3.5);"
                       "d := LREAL_TO_INT(-2.5); e := LREAL_TO_DINT(1234566.5); t := TRUNC(-2.7);");
    EXPECT_EQ(as_signed(p, "Main.a", 16), 2);
    EXPECT_EQ(as_signed(p, "Main.b", 16), 0);
    EXPECT_EQ(as_signed(p, "Main.c", 16), 4);
    EXPECT_EQ(as_signed(p, "Main.d", 16), -2);
    EXPECT_EQ(as_signed(p, "Main.e", 32), 1234566);
    EXPECT_EQ(as_signed(p, "Main.t", 32), -2);
}

TEST(ReferenceEvaluator, DivisionTruncatesAndModTakesTheDividendsSign) {
    const auto p = run("a, b, c, d : DINT; m : DINT := -2147483648;",
                       "a := -7 / 2; b := -7 MOD 3; c := 7 MOD -3; d := m / -1;");
    EXPECT_EQ(as_signed(p, "Main.a", 32), -3);
    EXPECT_EQ(as_signed(p, "Main.b", 32), -1);
    EXPECT_EQ(as_signed(p, "Main.c", 32), 1);
    EXPECT_EQ(as_signed(p, "Main.d", 32), -2147483648LL);
}

TEST(ReferenceEvaluator, DivisionByZeroIsAFault) {
    ReferenceProgram p("PROGRAM Main\nVAR a, z : DINT; END_VAR\na := 5;\na := a MOD z;\n"
                       "END_PROGRAM\n");
    ASSERT_TRUE(p.ok()) << p.errors();
    EXPECT_FALSE(p.scans(1));
    EXPECT_EQ(p.fault(), "division by zero in Main at line 4");
}

TEST(ReferenceEvaluator, AnIndexBeyond32BitsIsOutOfRange) {
    ReferenceProgram p("PROGRAM Main\nVAR a : ARRAY[0..9] OF DINT; i : LINT := 4294967298; "
                       "x : DINT; END_VAR\nx := a[i];\nEND_PROGRAM\n");
    ASSERT_TRUE(p.ok()) << p.errors();
    EXPECT_FALSE(p.scans(1));
    EXPECT_EQ(p.fault(), "array index out of range in Main at line 3");
}

TEST(ReferenceEvaluator, SubrangeViolationIsAFault) {
    ReferenceProgram p("PROGRAM Main\nVAR p : INT(0..100) := 100; END_VAR\np := p + 1;\n"
                       "END_PROGRAM\n");
    ASSERT_TRUE(p.ok()) << p.errors();
    EXPECT_FALSE(p.scans(1));
    EXPECT_EQ(p.fault(), "value out of subrange in Main at line 3");
}

TEST(ReferenceEvaluator, AForOverASubrangeEndsAtItsLastValue) {
    const auto p = run("k : INT(1..10); n : DINT;", "FOR k := 1 TO 10 DO n := n + k; END_FOR;");
    EXPECT_EQ(p.bits("Main.k"), 10u);
    EXPECT_EQ(p.bits("Main.n"), 55u);
}

TEST(ReferenceEvaluator, AForUpToTheEndOfItsTypeEndsThereWrapped) {
    const auto p = run("u : USINT; s : SINT; t : USINT(250..255); n, m, k : DINT;",
                       "FOR u := 250 TO 255 DO n := n + 1; END_FOR;"
                       "FOR s := -120 TO -128 BY -4 DO m := m + 1; END_FOR;"
                       "FOR t := 250 TO 255 DO k := k + 1; END_FOR;");
    EXPECT_EQ(p.bits("Main.n"), 6u);
    EXPECT_EQ(p.bits("Main.u"), 0u);
    EXPECT_EQ(p.bits("Main.m"), 3u);
    EXPECT_EQ(p.bits("Main.s"), 124u);
    EXPECT_EQ(p.bits("Main.k"), 6u);
    EXPECT_EQ(p.bits("Main.t"), 255u);
}

TEST(ReferenceEvaluator, ShiftsAndRotationsWorkAtTheTypesWidth) {
    const auto p =
        run("a, b, c : BYTE; w : WORD; d : DWORD; l : LWORD; x : BYTE;",
            "a := SHL(BYTE#16#81, 1); b := ROL(BYTE#16#81, 1); c := ROR(BYTE#16#81, 4);"
            "w := ROR(WORD#1, 1); d := SHR(DWORD#16#80000000, 31); l := SHL(LWORD#1, 63);"
            "x := SHL(BYTE#1, 8);");
    EXPECT_EQ(p.bits("Main.a"), 0x02u);
    EXPECT_EQ(p.bits("Main.b"), 0x03u);
    EXPECT_EQ(p.bits("Main.c"), 0x18u);
    EXPECT_EQ(p.bits("Main.w"), 0x8000u);
    EXPECT_EQ(p.bits("Main.d"), 1u);
    EXPECT_EQ(p.bits("Main.l"), 0x8000000000000000u);
    EXPECT_EQ(p.bits("Main.x"), 0u);
}

TEST(ReferenceEvaluator, BitOperationsAndComparisons) {
    const auto p = run("w : WORD := 16#F0F0; a, b : WORD; n : BOOL; lt, mixed, bit : BOOL; "
                       "u : UDINT := 4000000000; i : DINT := -1;",
                       "a := w AND 16#FF00; b := NOT w XOR 16#000F; n := NOT (3 > 2);"
                       "lt := -1 < 1; mixed := i < UDINT_TO_LINT(u); bit := w.4; w.0 := TRUE; "
                       "w.15 := FALSE;");
    EXPECT_EQ(p.bits("Main.a"), 0xF000u);
    EXPECT_EQ(p.bits("Main.b"), 0x0F00u);
    EXPECT_EQ(p.bits("Main.n"), 0u);
    EXPECT_EQ(p.bits("Main.lt"), 1u);
    // DINT widens to LINT (figure 11): -1 < 4000000000. A DINT and a UDINT have no common
    // type without a conversion: neither widens to the other.
    EXPECT_EQ(p.bits("Main.mixed"), 1u);
    EXPECT_EQ(p.bits("Main.bit"), 1u);
    EXPECT_EQ(p.bits("Main.w"), 0x70F1u);
}

TEST(ReferenceEvaluator, ACharIsItsCode) {
    const auto p = run("c : CHAR; n : USINT;", "c := CHAR#'A'; n := CHAR_TO_USINT(c) + 1;");
    EXPECT_EQ(p.bits("Main.c"), 65u);
    EXPECT_EQ(p.bits("Main.n"), 66u);
}

TEST(ReferenceEvaluator, RealArithmeticIsInTheTypesPrecision) {
    const auto p = run("a : REAL := 0.1; b : REAL := 0.2; r : REAL; x : LREAL := 0.1; l : LREAL;"
                       "s : REAL; e : LREAL; m : LREAL;",
                       "r := a + b; l := x + 0.2; s := SQRT(REAL#2.0); e := EXPT(2.0, 10);"
                       "m := ABS(-1.5) + MAX(1.0, 2.5);");
    EXPECT_EQ(p.bits("Main.r"), std::bit_cast<std::uint32_t>(0.1F + 0.2F));
    EXPECT_EQ(p.bits("Main.l"), std::bit_cast<std::uint64_t>(0.1 + 0.2));
    EXPECT_EQ(p.bits("Main.s"), std::bit_cast<std::uint32_t>(1.41421354F));
    EXPECT_EQ(p.bits("Main.e"), std::bit_cast<std::uint64_t>(1024.0));
    EXPECT_EQ(p.bits("Main.m"), std::bit_cast<std::uint64_t>(4.0));
}

TEST(ReferenceEvaluator, StringFunctionsCountFromOne) {
    const auto p =
        run("s : STRING := 'Hello'; a, b, c, d, e, f, g : STRING[20]; n, k, z : INT;",
            "n := LEN(s); a := LEFT(s, 2); b := RIGHT(s, 3); c := MID(s, 2, 2);"
            "d := CONCAT(s, ', ', 'world'); e := INSERT(s, 'XY', 2); f := DELETE(s, 2, 2);"
            "g := REPLACE(s, 'ipp', 2, 2); k := FIND(s, 'll'); z := FIND(s, 'x');");
    EXPECT_EQ(p.bits("Main.n"), 5u);
    EXPECT_EQ(p.string("Main.a"), "He");
    EXPECT_EQ(p.string("Main.b"), "llo");
    EXPECT_EQ(p.string("Main.c"), "el");
    EXPECT_EQ(p.string("Main.d"), "Hello, world");
    EXPECT_EQ(p.string("Main.e"), "HeXYllo");
    EXPECT_EQ(p.string("Main.f"), "Hlo");
    EXPECT_EQ(p.string("Main.g"), "Hipplo");
    EXPECT_EQ(p.bits("Main.k"), 3u);
    EXPECT_EQ(p.bits("Main.z"), 0u);
}

TEST(ReferenceEvaluator, IntegersConvertToTheirDecimalDigits) {
    const auto p = run("a, b, c : STRING; i : INT := -42; u : ULINT := 18446744073709551615;",
                       "a := INT_TO_STRING(i); b := ULINT_TO_STRING(u); c := DINT_TO_STRING(0);");
    EXPECT_EQ(p.string("Main.a"), "-42");
    EXPECT_EQ(p.string("Main.b"), "18446744073709551615");
    EXPECT_EQ(p.string("Main.c"), "0");
}

TEST(ReferenceEvaluator, TimeFunctionsAndTimeOfDayWrappingAtMidnight) {
    const auto p =
        run("a : TOD; b : TIME; c : DATE; d : TOD; e : TIME;",
            "a := ADD_TOD_TIME(TOD#23:00:00, T#2h); b := SUB_DT_DT(DT#2024-01-02-00:00:00, "
            "DT#2024-01-01-12:00:00); c := DT_TO_DATE(DT#1969-12-31-18:00:00);"
            "d := DT_TO_TOD(DT#1969-12-31-18:00:00); e := MUL_TIME(T#1500ms, 3);");
    constexpr std::uint64_t kHour = 3'600'000'000'000;
    EXPECT_EQ(p.bits("Main.a"), 1 * kHour);
    EXPECT_EQ(p.bits("Main.b"), 12 * kHour);
    EXPECT_EQ(p.bits("Main.c"), static_cast<std::uint64_t>(-24 * static_cast<std::int64_t>(kHour)));
    EXPECT_EQ(p.bits("Main.d"), 18 * kHour);
    EXPECT_EQ(p.bits("Main.e"), 4'500'000'000u);
}

// Table 30's rows as operators compute as the functions do: a time of day wraps at midnight.
TEST(ReferenceEvaluator, TimeOfDayOperatorsWrapAtMidnightAsTheFunctionsDo) {
    const auto p = run("late : TOD := TOD#23:00:00; early : LTOD := LTOD#01:00:00;"
                       "a, b : TOD; c, d : LTOD; e : TIME;",
                       "a := late + T#2h; b := late - T#49h; c := early - LTIME#2h;"
                       "d := early + LTIME#26h; e := late - TOD#01:00:00;");
    constexpr std::uint64_t kHour = 3'600'000'000'000;
    EXPECT_EQ(p.bits("Main.a"), 1 * kHour);
    EXPECT_EQ(p.bits("Main.b"), 22 * kHour);
    EXPECT_EQ(p.bits("Main.c"), 23 * kHour);
    EXPECT_EQ(p.bits("Main.d"), 3 * kHour);
    EXPECT_EQ(p.bits("Main.e"), 22 * kHour); // two times of day subtract to a duration
}

TEST(ReferenceEvaluator, LongTimeFunctionsAndTheOverloadedFormsAreTheirTable30Rows) {
    const auto p = run("a : LTOD; b : LTIME; c : LDT; d : TOD; e : LTIME; f : LTIME;",
                       "a := ADD_LTOD_LTIME(LTOD#23:00:00, LTIME#2h); b := SUB_LDATE_LDATE("
                       "LDATE#2024-01-02, D#2024-01-01); c := CONCAT_DATE_LTOD(D#1970-01-01, "
                       "LTOD#01:00:00); d := SUB(TOD#01:00:00, T#2h); e := MUL(LTIME#1500ms, 3);"
                       "f := SUB(DT#2024-01-02-00:00:00, LDT#2024-01-01-12:00:00);");
    constexpr std::uint64_t kHour = 3'600'000'000'000;
    EXPECT_EQ(p.bits("Main.a"), 1 * kHour);
    EXPECT_EQ(p.bits("Main.b"), 24 * kHour);
    EXPECT_EQ(p.bits("Main.c"), 1 * kHour);
    EXPECT_EQ(p.bits("Main.d"), 23 * kHour);
    EXPECT_EQ(p.bits("Main.e"), 4'500'000'000u);
    EXPECT_EQ(p.bits("Main.f"), 12 * kHour);
}

// ADD and MUL are extensible (table 24); on times each step is a row of table 30.
TEST(ReferenceEvaluator, ExtensibleAddAndMulOnTimesStepFromLeftToRight) {
    const auto p = run("late : TOD := TOD#23:00:00; t : TIME := T#1h; a : TOD; b, c : TIME;",
                       "a := ADD(late, t, t); b := ADD(t, t, T#1s); c := MUL(t, 2, 3);");
    constexpr std::uint64_t kHour = 3'600'000'000'000;
    EXPECT_EQ(p.bits("Main.a"), 1 * kHour);
    EXPECT_EQ(p.bits("Main.b"), 2 * kHour + 1'000'000'000);
    EXPECT_EQ(p.bits("Main.c"), 6 * kHour);
}

TEST(ReferenceEvaluator, AStringIsCutAtItsLength) {
    const auto p = run("s : STRING[3];", "s := 'abcdef';");
    EXPECT_EQ(p.string("Main.s"), "abc");
}

TEST(ReferenceEvaluator, SelectionFunctionsTakeEveryTypeIncludingStrings) {
    const auto p = run("g : BOOL; t : STRING := 'cdef'; a, b, c, d, e : STRING; k : INT := 2;"
                       "x : DINT; y : LREAL; tm : TIME;",
                       "a := SEL(g, t, CONCAT('Y', 'Z')); b := MUX(0, t, 'x', LEFT('Yab', 3));"
                       "c := MAX('abc', t, 'ab'); d := MIN('abc', t); e := LIMIT('b', 'a', t);"
                       "x := MUX(k, 10, 20, 30); y := LIMIT(0.0, 7.5, 5.0);"
                       "tm := MAX(T#1s, T#500ms);");
    EXPECT_EQ(p.string("Main.a"), "cdef");
    EXPECT_EQ(p.string("Main.b"), "cdef");
    EXPECT_EQ(p.string("Main.c"), "cdef");
    EXPECT_EQ(p.string("Main.d"), "abc");
    EXPECT_EQ(p.string("Main.e"), "b");
    EXPECT_EQ(p.bits("Main.x"), 30u);
    EXPECT_EQ(p.bits("Main.y"), std::bit_cast<std::uint64_t>(5.0));
    EXPECT_EQ(p.bits("Main.tm"), 1'000'000'000u);
}

TEST(ReferenceEvaluator, ArgumentsArePassedByValueWhateverCallsTheyContain) {
    ReferenceProgram p(R"(
FUNCTION F : DINT
  VAR_INPUT w : DWORD; s : STRING; b : BOOL; END_VAR
  F := LEN(s) * 10 + BOOL_TO_DINT(b);
END_FUNCTION
FUNCTION Six : DINT
  VAR_INPUT a, b, c, d, e, f : BOOL; END_VAR
  Six := BOOL_TO_DINT(a) * 100000 + BOOL_TO_DINT(b) * 10000 + BOOL_TO_DINT(c) * 1000
         + BOOL_TO_DINT(d) * 100 + BOOL_TO_DINT(e) * 10 + BOOL_TO_DINT(f);
END_FUNCTION
PROGRAM Main
  VAR t : STRING := 'abc'; sa : STRING := 'a'; sb : STRING := 'b'; r, q, z : DINT; END_VAR
  r := F(DWORD#1, t, t = 'abc');
  q := Six(sa = sb, sa <> sb, sa < sb, sa <= sb, sa > sb, sa >= sb);
  z := Six(FALSE, FALSE, FALSE, FALSE, FALSE, sa >= sb);
END_PROGRAM
)");
    ASSERT_TRUE(p.ok()) << p.errors();
    ASSERT_TRUE(p.scans(1)) << p.fault();
    EXPECT_EQ(p.bits("Main.r"), 31u);
    EXPECT_EQ(p.bits("Main.q"), 11100u);
    EXPECT_EQ(p.bits("Main.z"), 0u);
}

TEST(ReferenceEvaluator, FunctionBlocksKeepStateAcrossScansAndInOutsAlias) {
    ReferenceProgram p(R"(
FUNCTION_BLOCK Accumulator
  VAR_INPUT add : DINT; END_VAR
  VAR_OUTPUT sum : DINT; END_VAR
  VAR_IN_OUT log : ARRAY[0..3] OF DINT; END_VAR
  sum := sum + add;
  log[sum MOD 4] := sum;
END_FUNCTION_BLOCK
FUNCTION Swap : BOOL
  VAR_IN_OUT a, b : INT; END_VAR
  VAR t : INT; END_VAR
  t := a; a := b; b := t; Swap := TRUE;
END_FUNCTION
PROGRAM Main
  VAR acc : Accumulator; history : ARRAY[0..3] OF DINT; total : DINT; x : INT := 1; y : INT := 2;
      ok : BOOL; END_VAR
  acc(add := 3, log := history, sum => total);
  ok := Swap(x, y);
END_PROGRAM
)");
    ASSERT_TRUE(p.ok()) << p.errors();
    ASSERT_TRUE(p.scans(3)) << p.fault();
    EXPECT_EQ(p.bits("Main.total"), 9u);
    EXPECT_EQ(p.bits("Main.acc.sum"), 9u);
    EXPECT_EQ(p.bits("Main.history[3]"), 3u);
    EXPECT_EQ(p.bits("Main.history[2]"), 6u);
    EXPECT_EQ(p.bits("Main.history[1]"), 9u);
    EXPECT_EQ(p.bits("Main.x"), 2u); // swapped three times
    EXPECT_EQ(p.bits("Main.y"), 1u);
}

TEST(ReferenceEvaluator, ArraysStructsAndControlFlow) {
    ReferenceProgram p(R"(
TYPE Point : STRUCT x, y : INT := 1; tag : STRING[4] := 'p'; END_STRUCT; END_TYPE
FUNCTION FirstOver : INT
  VAR_INPUT limit : INT; END_VAR
  VAR i : INT; END_VAR
  FOR i := 1 TO 100 DO
    IF i * i > limit THEN FirstOver := i; RETURN; END_IF;
  END_FOR;
  FirstOver := -1;
END_FUNCTION
PROGRAM Main
  VAR grid : ARRAY[0..2, 1..3] OF DINT; i, j : INT; n, w, r, c, e : DINT; pts : ARRAY[1..2] OF Point;
      f : INT; k : INT := 7; sel : ULINT := 9542150923762281093; big : BOOL; END_VAR
  FOR i := 0 TO 2 DO FOR j := 1 TO 3 DO grid[i, j] := i * 10 + j; END_FOR; END_FOR;
  FOR i := 10 TO 1 BY -3 DO n := n + i; END_FOR;
  WHILE w < 100 DO w := w + 7; IF w MOD 2 = 0 THEN CONTINUE; END_IF; c := c + 1; END_WHILE;
  REPEAT r := r + 1; IF r = 5 THEN EXIT; END_IF; UNTIL r >= 10 END_REPEAT;
  pts[2].x := pts[1].y + 5;
  f := FirstOver(50);
  CASE k OF 1..5: e := 1; 6, 7: e := 2; ELSE e := 3; END_CASE;
  CASE sel OF 9542150923762281093: big := TRUE; END_CASE;
END_PROGRAM
)");
    ASSERT_TRUE(p.ok()) << p.errors();
    ASSERT_TRUE(p.scans(1)) << p.fault();
    EXPECT_EQ(p.bits("Main.grid[2, 3]"), 23u);
    EXPECT_EQ(p.bits("Main.grid[1,1]"), 11u);
    EXPECT_EQ(p.bits("Main.n"), 22u); // 10 + 7 + 4 + 1
    EXPECT_EQ(p.bits("Main.i"), static_cast<std::uint16_t>(-2));
    EXPECT_EQ(p.bits("Main.w"), 105u);
    EXPECT_EQ(p.bits("Main.c"), 8u); // 7, 21, 35, ..., 105: the odd ones of 15 steps
    EXPECT_EQ(p.bits("Main.r"), 5u);
    EXPECT_EQ(p.bits("Main.pts[2].x"), 6u);
    EXPECT_EQ(p.string("Main.pts[1].tag"), "p");
    EXPECT_EQ(p.bits("Main.f"), 8u);
    EXPECT_EQ(p.bits("Main.e"), 2u);
    EXPECT_EQ(p.bits("Main.big"), 1u);
}

TEST(ReferenceEvaluator, GlobalsAndAConfigurationWithOneTask) {
    ReferenceProgram p(R"(
VAR_GLOBAL count : DINT; END_VAR
PROGRAM Main
  VAR_EXTERNAL total : DINT; END_VAR
  VAR n : INT; END_VAR
  n := n + 1; total := total + n; count := count + 2;
END_PROGRAM
PROGRAM Other
  VAR_EXTERNAL total : DINT; END_VAR
  total := 1000;
END_PROGRAM
CONFIGURATION Cell
  VAR_GLOBAL total : DINT; END_VAR
  RESOURCE Cpu ON PLC
    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
    TASK Slow(INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM Inst1 WITH Slow : Other;
    PROGRAM Inst0 WITH Fast : Main;
  END_RESOURCE
END_CONFIGURATION
)");
    ASSERT_TRUE(p.ok()) << p.errors();
    ASSERT_TRUE(p.scans(3)) << p.fault();
    EXPECT_EQ(p.bits("Cell.total"), 6u);
    EXPECT_EQ(p.bits("Inst0.n"), 3u);
    EXPECT_EQ(p.bits("count"), 6u);
}

TEST(ReferenceEvaluator, EnFalseSkipsTheCallAndKeepsTheAssignedVariable) {
    ReferenceProgram p(R"(
FUNCTION_BLOCK Counter
  VAR_OUTPUT n : INT; END_VAR
  n := n + 1;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR c : Counter; go : BOOL; x : INT := 7; y : INT := 7; z : INT; ok1, ok2, ok3 : BOOL := TRUE;
      s : STRING := 'keep'; END_VAR
  c(EN := go, ENO => ok1);
  x := ABS(EN := go, IN := -3, ENO => ok2);
  z := 10 + ABS(EN := go, IN := -3);
  s := LEFT(EN := go, IN := 'abc', L := 1);
  y := ABS(EN := TRUE, IN := -3, ENO => ok3);
END_PROGRAM
)");
    ASSERT_TRUE(p.ok()) << p.errors();
    ASSERT_TRUE(p.scans(1)) << p.fault();
    EXPECT_EQ(p.bits("Main.c.n"), 0u);
    EXPECT_EQ(p.bits("Main.ok1"), 0u);
    EXPECT_EQ(p.bits("Main.x"), 7u);
    EXPECT_EQ(p.bits("Main.ok2"), 0u);
    EXPECT_EQ(p.bits("Main.z"), 10u); // a skipped function gives 0 inside an expression
    EXPECT_EQ(p.string("Main.s"), "keep");
    EXPECT_EQ(p.bits("Main.y"), 3u);
    EXPECT_EQ(p.bits("Main.ok3"), 1u);
}

TEST(ReferenceEvaluator, RefusesWhatItDoesNotModel) {
    ReferenceProgram p("PROGRAM Main\nVAR p : POINTER TO INT; x : INT; END_VAR\np := ADR(x);\n"
                       "END_PROGRAM\n");
    EXPECT_FALSE(p.ok());
    EXPECT_NE(p.errors().find("not supported by the reference evaluator"), std::string::npos)
        << p.errors();
}

TEST(ReferenceEvaluator, RefusesConversionsTheStandardLeavesOpenBeforeRunning) {
    ReferenceProgram p("PROGRAM Main\nVAR t : TIME; r : REAL; END_VAR\nr := TIME_TO_REAL(t);\n"
                       "END_PROGRAM\n");
    EXPECT_FALSE(p.ok());
    EXPECT_NE(p.errors().find("not supported by the reference evaluator: the conversion "
                              "TIME_TO_REAL"),
              std::string::npos)
        << p.errors();
}

TEST(ReferenceEvaluator, ReportsFrontEndErrors) {
    ReferenceProgram p("PROGRAM Main\nVAR i : INT; d : DINT; END_VAR\ni := d;\nEND_PROGRAM\n");
    EXPECT_FALSE(p.ok());
    EXPECT_NE(p.errors().find("main.st:3"), std::string::npos) << p.errors();
}

} // namespace
} // namespace eposp::reference

namespace eposp::reference {
namespace {

// docs/st-language.md "Calling a PROGRAM": the program's single instance runs at each call
// by its name, from an FB or another program, and `P.x` reaches its variables.
TEST(ReferenceEvaluator, AProgramCalledByItsNameKeepsItsStateAcrossCalls) {
    ReferenceProgram program(R"(
PROGRAM Counter
VAR_INPUT Step : DINT := 1; END_VAR
VAR_OUTPUT Count : DINT; END_VAR
VAR calls : DINT; END_VAR
calls := calls + 1;
Count := Count + Step;
END_PROGRAM
FUNCTION_BLOCK Driver
VAR_OUTPUT seen : DINT; END_VAR
Counter(Step := 10);
seen := Counter.Count;
END_FUNCTION_BLOCK
PROGRAM Main
VAR d : Driver; a : DINT; b : DINT; c : DINT; END_VAR
Counter.calls := Counter.calls + 100;
Counter(Step := 1);
a := Counter.Count;
d();
b := d.seen;
c := Counter.calls;
END_PROGRAM
CONFIGURATION Cell RESOURCE R ON PLC
  TASK T(INTERVAL := T#10ms, PRIORITY := 1);
  PROGRAM Inst WITH T : Main;
END_RESOURCE END_CONFIGURATION
)");
    ASSERT_TRUE(program.ok()) << program.errors();
    ASSERT_TRUE(program.scans(3)) << program.fault();
    EXPECT_EQ(program.bits("Inst.a"), 23u);
    EXPECT_EQ(program.bits("Inst.b"), 33u);
    EXPECT_EQ(program.bits("Inst.c"), 306u);
    EXPECT_EQ(program.bits("Counter.Count"), 33u);
}

} // namespace
} // namespace eposp::reference
