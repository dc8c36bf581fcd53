// STRING handling compiled and run (vm/README "Strings"): truncation at the capacity,
// CONCAT folded left to right, the string functions and conversions, comparisons.
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

} // namespace
} // namespace eposp::compiler::test
