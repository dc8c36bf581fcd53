// STRING and WSTRING handling compiled and run (vm/README "Strings"): truncation at the
// capacity, CONCAT folded left to right, the string functions and conversions, comparisons.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(Strings, AssignmentTruncatesAtTheCapacity) {
    StProgram run(R"(
PROGRAM Main
VAR short : STRING[5]; long : STRING := 'Hello World'; other : STRING[5] := 'abc'; END_VAR
short := 'Hello World';
other := long;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.short"), "Hello");
    EXPECT_EQ(run.get_string("Main.other"), "Hello");
    EXPECT_EQ(run.get_string("Main.long"), "Hello World");
}

TEST(Strings, FunctionsAndConversions) {
    StProgram run(R"(
PROGRAM Main
VAR
  s : STRING := 'abcdef';
  c, l, r, m, ins, del, rep, num : STRING;
  n, f : INT;
  eq, lt : BOOL;
  back : DINT;
END_VAR
c := CONCAT('x', s, '-', INT_TO_STRING(-42));
n := LEN(c);
l := LEFT(s, 2);
r := RIGHT(s, 2);
m := MID(s, 3, 2);
ins := INSERT(s, '++', 3);
del := DELETE(s, 2, 2);
rep := REPLACE(s, 'ZZ', 3, 1);
f := FIND(s, 'cd');
num := DINT_TO_STRING(12345);
back := STRING_TO_DINT(num) + 1;
eq := s = 'abcdef';
lt := 'abc' < s;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.c"), "xabcdef--42");
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 11);
    EXPECT_EQ(run.get_string("Main.l"), "ab");
    EXPECT_EQ(run.get_string("Main.r"), "ef");
    EXPECT_EQ(run.get_string("Main.m"), "bcd");
    EXPECT_EQ(run.get_string("Main.ins"), "abc++def");
    EXPECT_EQ(run.get_string("Main.del"), "adef");
    EXPECT_EQ(run.get_string("Main.rep"), "ZZdef"); // L = 3 characters at P = 1
    EXPECT_EQ(run.get<std::int16_t>("Main.f"), 3);
    EXPECT_EQ(run.get_string("Main.num"), "12345");
    EXPECT_EQ(run.get<std::int32_t>("Main.back"), 12346);
    EXPECT_TRUE(run.get<bool>("Main.eq"));
    EXPECT_TRUE(run.get<bool>("Main.lt"));
}

TEST(Strings, ConcatIntoAnArgumentOfItself) {
    StProgram run(R"(
PROGRAM Main
VAR s : STRING[8] := 'ab'; t : STRING := 'x'; END_VAR
s := CONCAT(s, s, s, s, s);
t := CONCAT('1', '2', t);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.s"), "abababab");
    EXPECT_EQ(run.get_string("Main.t"), "12x");
}

TEST(Strings, PassedToFunctionsAndFbs) {
    StProgram run(R"(
FUNCTION Greet : STRING
  VAR_INPUT name : STRING[10]; END_VAR
  Greet := CONCAT('Hi ', name);
END_FUNCTION
PROGRAM Main
VAR g : STRING; END_VAR
g := Greet('Bob');
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.g"), "Hi Bob");
}

TEST(Wstrings, FunctionsWorkAsOnStringsCountingUtf16Units) {
    StProgram run(R"(
PROGRAM Main
VAR
  w : WSTRING[10] := "abcdef";
  c, l, r, m, ins, del, rep : WSTRING[20];
  n, f, euro_at : INT;
  eq, lt, gt : BOOL;
END_VAR
c := CONCAT("x", w, "-", "€");
n := LEN(c);
l := LEFT(w, 2);
r := RIGHT(w, 2);
m := MID(w, 3, 2);
ins := INSERT(w, "++", 3);
del := DELETE(w, 2, 2);
rep := REPLACE(w, "ZZ", 3, 1);
f := FIND(w, "cd");
euro_at := FIND(c, "€");
eq := w = "abcdef";
lt := "abc" < w;
gt := "€" > "ä";
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_wstring("Main.c"), u"xabcdef-\u20ac");
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 9);
    EXPECT_EQ(run.get_wstring("Main.l"), u"ab");
    EXPECT_EQ(run.get_wstring("Main.r"), u"ef");
    EXPECT_EQ(run.get_wstring("Main.m"), u"bcd");
    EXPECT_EQ(run.get_wstring("Main.ins"), u"abc++def");
    EXPECT_EQ(run.get_wstring("Main.del"), u"adef");
    EXPECT_EQ(run.get_wstring("Main.rep"), u"ZZdef");
    EXPECT_EQ(run.get<std::int16_t>("Main.f"), 3);
    EXPECT_EQ(run.get<std::int16_t>("Main.euro_at"), 9);
    EXPECT_TRUE(run.get<bool>("Main.eq"));
    EXPECT_TRUE(run.get<bool>("Main.lt"));
    EXPECT_TRUE(run.get<bool>("Main.gt")); // U+20AC orders after U+00E4
}

TEST(Wstrings, AssignmentAndResultsTruncateAtTheCapacity) {
    StProgram run(R"(
PROGRAM Main
VAR
  long : WSTRING := "Hello World"; short, joined : WSTRING[5]; self : WSTRING[8] := "ab";
END_VAR
short := long;
joined := CONCAT(long, "!");
self := CONCAT(self, self, self, self, self);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_wstring("Main.short"), u"Hello");
    EXPECT_EQ(run.get_wstring("Main.joined"), u"Hello");
    EXPECT_EQ(run.get_wstring("Main.self"), u"abababab");
}

TEST(Wstrings, CharacterConversionsOfTable22) {
    StProgram run(R"(
PROGRAM Main
VAR
  s : STRING := 'ab'; empty : STRING; c, first, none : CHAR := CHAR#'x'; one : STRING;
  w : WSTRING := "€b"; wc, wfirst : WCHAR := WCHAR#"Z"; wone : WSTRING;
END_VAR
one := CHAR_TO_STRING(c);
first := STRING_TO_CHAR(s);
none := STRING_TO_CHAR(empty);
wone := WCHAR_TO_WSTRING(wc);
wfirst := WSTRING_TO_WCHAR(w);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.one"), "x");
    EXPECT_EQ(run.get<std::uint8_t>("Main.first"), 'a');
    EXPECT_EQ(run.get<std::uint8_t>("Main.none"), 0);
    EXPECT_EQ(run.get_wstring("Main.wone"), u"Z");
    EXPECT_EQ(run.get<std::uint16_t>("Main.wfirst"), 0x20AC);
}

// A text converted to its own width is assigned, cut at the capacity it goes to: these called
// the other width's conversion, which read a STRING as a WSTRING ('?c' for 'abc').
TEST(Wstrings, ConversionToTheSameWidthIsAnAssignment) {
    StProgram run(R"(
PROGRAM Main
VAR
  s : STRING[10] := 'abc'; w : WSTRING[10] := "d€f";
  whole, same : STRING; cut : STRING[2]; wide : WSTRING; wcut : WSTRING[2];
END_VAR
whole := TO_STRING(s);
same := STRING_TO_STRING(s);
cut := TO_STRING(s);
wide := TO_WSTRING(w);
wcut := WSTRING_TO_WSTRING(w);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.whole"), "abc");
    EXPECT_EQ(run.get_string("Main.same"), "abc");
    EXPECT_EQ(run.get_string("Main.cut"), "ab");
    EXPECT_EQ(run.get_wstring("Main.wide"), u"d€f");
    EXPECT_EQ(run.get_wstring("Main.wcut"), u"d€");
}

// A conversion's result is the STRING[80] or WSTRING[80] it is typed, also when stored straight
// into a longer text: these kept all 90 characters of s100.
TEST(Wstrings, AConversionIntoALongerTextIsCutAtItsOwnCapacity) {
    StProgram run(R"(
PROGRAM Main
VAR
  s100 : STRING[100]; s200 : STRING[200]; w100 : WSTRING[100];
END_VAR
s100 := '123456789012345678901234567890123456789012345678901234567890123456789012345678901234567890';
s200 := TO_STRING(s100);
w100 := STRING_TO_WSTRING(s100);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.s200").size(), 80U);
    EXPECT_EQ(run.get_wstring("Main.w100").size(), 80U);
}

} // namespace
} // namespace eposp::compiler::test
