// SEL, MUX, MAX, MIN and LIMIT on every elementary type (IEC 61131-3 ed. 3, 6.6.2.5.9), strings
// compared lexicographically, with inputs that are string functions in every position; the
// comparison functions on strings, times and dates.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(SelectionOnStrings, AStringFunctionOfALiteralAsLastInputIsNotChosenWrongly) {
    StProgram run(R"(
PROGRAM Main
VAR g : BOOL; t : STRING := 'cdef'; u : STRING := 'wxyz';
    s1, s2, s3, s4, s5, s6, s7 : STRING; END_VAR
s1 := SEL(g, t, CONCAT('Y', 'Z'));
s2 := MUX(0, t, 'x', LEFT('Yab', 3));
s3 := SEL(FALSE, u, LEFT('5c', 2));
s4 := SEL(TRUE, u, LEFT('5c', 2));
s5 := MUX(2, t, 'x', LEFT('Yab', 3));
s6 := MUX(1, t, 'x', LEFT('Yab', 3));
s7 := SEL(NOT g, CONCAT('Y', 'Z'), t);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.s1"), "cdef");
    EXPECT_EQ(run.get_string("Main.s2"), "cdef");
    EXPECT_EQ(run.get_string("Main.s3"), "wxyz");
    EXPECT_EQ(run.get_string("Main.s4"), "5c");
    EXPECT_EQ(run.get_string("Main.s5"), "Yab");
    EXPECT_EQ(run.get_string("Main.s6"), "x");
    EXPECT_EQ(run.get_string("Main.s7"), "cdef");
}

TEST(SelectionOnStrings, MaxMinLimitCompareLexicographically) {
    StProgram run(R"(
PROGRAM Main
VAR t : STRING := 'abc'; w : WSTRING := "b";
    max1, max2, min1, min2, lim1, lim2, lim3, lim4 : STRING; wmax : WSTRING; END_VAR
max1 := MAX('abc', t, 'abd', 'ab');
max2 := MAX(CONCAT(t, 'z'), LEFT('abd', 3), t);
min1 := MIN(t, 'abd', 'ab', 'b');
min2 := MIN(RIGHT('zab', 2), t, CONCAT('a', 'c'));
lim1 := LIMIT('b', t, 'c');
lim2 := LIMIT('b', 'zz', LEFT('cd', 1));
lim3 := LIMIT(LEFT('bx', 1), CONCAT('b', 'b'), 'c');
lim4 := LIMIT(t, MID('xaby', 2, 2), CONCAT(t, 'd'));
wmax := MAX(w, "a", CONCAT("b", "c"));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.max1"), "abd");
    EXPECT_EQ(run.get_string("Main.max2"), "abd");
    EXPECT_EQ(run.get_string("Main.min1"), "ab");
    EXPECT_EQ(run.get_string("Main.min2"), "ab");
    EXPECT_EQ(run.get_string("Main.lim1"), "b");
    EXPECT_EQ(run.get_string("Main.lim2"), "c");
    EXPECT_EQ(run.get_string("Main.lim3"), "bb");
    EXPECT_EQ(run.get_string("Main.lim4"), "abc"); // 'ab' is below the low bound
    EXPECT_EQ(run.get_wstring("Main.wmax"), u"bc");
}

// Inputs that are all literals, empty ones included, take the longest literal's capacity from
// the typing stage (at least 1: no value is a STRING[0]).
TEST(SelectionOnStrings, EmptyLiteralsAlone) {
    StProgram run(R"(
PROGRAM Main
VAR b : BOOL; i : INT := 2; j : INT := 1; s1, s2, s3, s4, s5, s6 : STRING; w : WSTRING; END_VAR
s1 := SEL(b, '', '');
s2 := MAX('', '');
s3 := MUX(i, 'a', '', 'abc');
s4 := MUX(j, 'a', '', 'abc');
s5 := CONCAT(MIN('', ''), 'x', LIMIT('', 'q', ''));
s6 := MUX(0, 'a', '', 'abc');
w := SEL(NOT b, "", "");
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.s1"), "");
    EXPECT_EQ(run.get_string("Main.s2"), "");
    EXPECT_EQ(run.get_string("Main.s3"), "abc");
    EXPECT_EQ(run.get_string("Main.s4"), "");
    EXPECT_EQ(run.get_string("Main.s5"), "x");
    EXPECT_EQ(run.get_string("Main.s6"), "a");
    EXPECT_EQ(run.get_wstring("Main.w"), u"");
}

// Every input position holds a string function once, for each selection function.
TEST(SelectionOnStrings, StringFunctionsInEveryPosition) {
    StProgram run(R"(
PROGRAM Main
VAR k : INT := 1; g : BOOL := TRUE; t : STRING := 'mm';
    a1, a2, b1, b2, b3, c1, c2, c3 : STRING; END_VAR
a1 := SEL(g, LEFT('xyz', 2), t);
a2 := SEL(g, t, LEFT('xyz', 2));
b1 := MUX(k, LEFT('aaa', 1), CONCAT('b', 'b'), t);
b2 := MUX(k + 1, t, LEFT('aaa', 1), CONCAT('c', 'c'));
b3 := MUX(k - 1, CONCAT('d', 'd'), t, LEFT('aaa', 1));
c1 := MAX(CONCAT('z', 'z'), t, LEFT('a', 1));
c2 := MIN(t, CONCAT('z', 'z'), LEFT('a', 1));
c3 := LIMIT(CONCAT('b', 'b'), LEFT('zzz', 3), CONCAT('y', 'y'));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.a1"), "mm");
    EXPECT_EQ(run.get_string("Main.a2"), "xy");
    EXPECT_EQ(run.get_string("Main.b1"), "bb");
    EXPECT_EQ(run.get_string("Main.b2"), "cc");
    EXPECT_EQ(run.get_string("Main.b3"), "dd");
    EXPECT_EQ(run.get_string("Main.c1"), "zz");
    EXPECT_EQ(run.get_string("Main.c2"), "a");
    EXPECT_EQ(run.get_string("Main.c3"), "yy");
}

TEST(SelectionOnTimes, MaxMinLimitSelMuxOnTimesAndDates) {
    StProgram run(R"(
PROGRAM Main
VAR t : TIME := T#2s; lt : LTIME := LTIME#5us; d : DATE := D#2024-03-01;
    tod1 : TOD := TOD#12:00:00; dt1 : DT := DT#2024-03-01-12:00:00;
    rt1, rt2, rt3, rt4 : TIME; rlt : LTIME; rd1, rd2 : DATE; rtod : TOD; rdt1, rdt2 : DT;
END_VAR
rt1 := MAX(T#1s, t, T#500ms);
rt2 := MIN(t, T#1s, T#3s);
rt3 := LIMIT(T#0s, t - T#5s, T#10s);
rt4 := MUX(1, T#1s, t);
rlt := LIMIT(LTIME#1us, lt, LTIME#3us);
rd1 := MAX(d, D#2023-12-31, D#2024-02-29);
rd2 := SEL(TRUE, d, D#2000-01-01);
rtod := MIN(tod1, TOD#08:30:00);
rdt1 := LIMIT(DT#2024-01-01-00:00:00, dt1, DT#2024-02-01-00:00:00);
rdt2 := MAX(dt1, DT#2024-03-01-12:00:01);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int64_t>("Main.rt1"), 2'000'000'000);
    EXPECT_EQ(run.get<std::int64_t>("Main.rt2"), 1'000'000'000);
    EXPECT_EQ(run.get<std::int64_t>("Main.rt3"), 0);
    EXPECT_EQ(run.get<std::int64_t>("Main.rt4"), 2'000'000'000);
    EXPECT_EQ(run.get<std::int64_t>("Main.rlt"), 3'000);
    StProgram expected(R"(
PROGRAM Main
VAR d : DATE := D#2024-03-01; d2 : DATE := D#2000-01-01; tod1 : TOD := TOD#08:30:00;
    dt1 : DT := DT#2024-02-01-00:00:00; dt2 : DT := DT#2024-03-01-12:00:01; END_VAR
END_PROGRAM
)");
    ASSERT_TRUE(expected.ok()) << expected.errors();
    ASSERT_TRUE(expected.scans(1)) << expected.fault();
    EXPECT_EQ(run.get<std::int64_t>("Main.rd1"), expected.get<std::int64_t>("Main.d"));
    EXPECT_EQ(run.get<std::int64_t>("Main.rd2"), expected.get<std::int64_t>("Main.d2"));
    EXPECT_EQ(run.get<std::int64_t>("Main.rtod"), expected.get<std::int64_t>("Main.tod1"));
    EXPECT_EQ(run.get<std::int64_t>("Main.rdt1"), expected.get<std::int64_t>("Main.dt1"));
    EXPECT_EQ(run.get<std::int64_t>("Main.rdt2"), expected.get<std::int64_t>("Main.dt2"));
}

// The other elementary types (ULINT and LWORD compared unsigned), and the comparison
// operators on dates, times of day, LTIME, WSTRING and CHAR.
TEST(SelectionOnEveryType, NumbersBitStringsCharactersAndComparisonOperators) {
    StProgram run(R"(
PROGRAM Main
VAR c : CHAR := CHAR#'b'; wc : WCHAR := WCHAR#"b"; rc : CHAR; rwc : WCHAR;
    b : BOOL; lw : LWORD; u : ULINT; s : SINT; r : REAL; l : LREAL; bt : BYTE;
    d1 : DATE := D#2024-01-02; tod1 : TOD := TOD#10:00:00; dt1 : DT := DT#2024-01-02-10:00:00; lt : LTIME := LTIME#1us;
    bits : DINT; ws : WSTRING := "b"; END_VAR
rc := MAX(c, CHAR#'a', CHAR#'c');
rwc := MIN(wc, WCHAR#"a");
b := MAX(FALSE, TRUE);
lw := MAX(LWORD#16#8000000000000000, LWORD#1);
u := LIMIT(ULINT#1, ULINT#16#FFFFFFFFFFFFFFFF, ULINT#16#8000000000000001);
s := MIN(SINT#-5, SINT#3);
r := MAX(REAL#1.5, REAL#-2.0);
l := LIMIT(0.0, 7.5, 5.0);
bt := MUX(2, BYTE#1, BYTE#2, BYTE#255);
bits := BOOL_TO_DINT(d1 < D#2024-01-03) + 2 * BOOL_TO_DINT(tod1 >= TOD#10:00:00)
      + 4 * BOOL_TO_DINT(dt1 <> DT#2024-01-02-10:00:00) + 8 * BOOL_TO_DINT(lt > LTIME#999ns)
      + 16 * BOOL_TO_DINT(ws >= "a") + 32 * BOOL_TO_DINT(c = CHAR#'b') + 64 * BOOL_TO_DINT(GT(c, CHAR#'a'));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::uint8_t>("Main.rc"), 'c');
    EXPECT_EQ(run.get<std::uint16_t>("Main.rwc"), 'a');
    EXPECT_EQ(run.get<bool>("Main.b"), true);
    EXPECT_EQ(run.get<std::uint64_t>("Main.lw"), 0x8000000000000000ULL);
    EXPECT_EQ(run.get<std::uint64_t>("Main.u"), 0x8000000000000001ULL);
    EXPECT_EQ(run.get<std::int8_t>("Main.s"), -5);
    EXPECT_EQ(run.get<float>("Main.r"), 1.5f);
    EXPECT_EQ(run.get<double>("Main.l"), 5.0);
    EXPECT_EQ(run.get<std::uint8_t>("Main.bt"), 255);
    EXPECT_EQ(run.get<std::int32_t>("Main.bits"), 1 + 2 + 8 + 16 + 32 + 64);
}

TEST(ComparisonFunctions, OnStringsTimesAndDates) {
    StProgram run(R"(
PROGRAM Main
VAR s : STRING := 'b'; w : WSTRING := "b"; t : TIME := T#1s; d : DATE := D#2024-01-02;
    tod1 : TOD := TOD#10:00:00; dt1 : DT := DT#2024-01-02-10:00:00; bits : DINT; END_VAR
bits := BOOL_TO_DINT(GT('c', s, 'a'))
      + 2 * BOOL_TO_DINT(GE(s, 'b', CONCAT('a', 'z')))
      + 4 * BOOL_TO_DINT(EQ(s, LEFT('bc', 1), 'b'))
      + 8 * BOOL_TO_DINT(LE('a', s, 'bb'))
      + 16 * BOOL_TO_DINT(LT(s, 'a'))
      + 32 * BOOL_TO_DINT(NE(s, 'b'))
      + 64 * BOOL_TO_DINT(GT(w, "a"))
      + 128 * BOOL_TO_DINT(LT(T#500ms, t, T#2s))
      + 256 * BOOL_TO_DINT(GE(d, D#2024-01-02, D#2023-01-01))
      + 512 * BOOL_TO_DINT(EQ(tod1, TOD#10:00:00))
      + 1024 * BOOL_TO_DINT(NE(dt1, DT#2024-01-02-10:00:00))
      + 2048 * BOOL_TO_DINT(LE(dt1, DT#2024-01-02-10:00:01));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.bits"), 1 + 2 + 4 + 8 + 64 + 128 + 256 + 512 + 2048);
}

} // namespace
} // namespace eposp::compiler::test
