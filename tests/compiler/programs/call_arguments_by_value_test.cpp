// A function's arguments are evaluated and passed by value (IEC 61131-3 ed. 3, 6.6.1.7): an
// argument whose evaluation needs a call, a host function (string comparisons, string
// functions, conversions) or a string temporary must not disturb the arguments placed before
// it, whether the call is kept or inlined.
#include "codegen_harness.hpp"

#include <algorithm>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

/// The names of the functions whose bodies replace a call somewhere in `image`.
std::vector<std::string> inlined_callees(const vm::Image& image) {
    std::vector<std::string> names;
    for (const vm::Pou& pou : image.pous) {
        for (const vm::InlinedCall& call : pou.inlined) {
            names.push_back(image.pous[call.callee].name);
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

TEST(CallArguments, StringComparisonsDoNotOverwriteEarlierBoolArguments) {
    StProgram run(R"(
FUNCTION Bits : DINT
  VAR_INPUT b0, b1, b2, b3, b4, b5 : BOOL; END_VAR
  Bits := BOOL_TO_DINT(b0) + 2 * BOOL_TO_DINT(b1) + 4 * BOOL_TO_DINT(b2)
        + 8 * BOOL_TO_DINT(b3) + 16 * BOOL_TO_DINT(b4) + 32 * BOOL_TO_DINT(b5);
END_FUNCTION

PROGRAM Main
VAR sa : STRING := 'abc'; sb : STRING := 'abd'; all, last, equal : DINT; END_VAR
all := Bits(sa = sb, sa <> sb, sa < sb, sa <= sb, sa > sb, sa >= sb);
last := Bits(FALSE, FALSE, FALSE, FALSE, FALSE, sa >= sb);
equal := Bits(sa = sa, sa <> sa, sa < sa, sa <= sa, sa > sa, sa >= sa);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.all"), 2 + 4 + 8);
    EXPECT_EQ(run.get<std::int32_t>("Main.last"), 0);
    EXPECT_EQ(run.get<std::int32_t>("Main.equal"), 1 + 8 + 32);
}

// Three arguments: the comparison's native writes its pointers where the DWORD and the
// STRING were placed.
constexpr const char* kWordStringBool = R"(
FUNCTION F : DINT
  VAR_INPUT w : DWORD; s : STRING; b : BOOL; END_VAR
  F := LEN(s) * 10 + BOOL_TO_DINT(b) + 1000 * DWORD_TO_DINT(w);
END_FUNCTION
)";

TEST(CallArguments, AComparisonAfterAStringArgumentKeepsIt) {
    StProgram run(std::string(kWordStringBool) + R"(
PROGRAM Main
VAR t : STRING := 'abc'; r1, r2, r3 : DINT; END_VAR
r1 := F(DWORD#1, t, t = 'abc');
r2 := F(b := t <> 'abc', s := CONCAT(t, 'de'), w := 2);
r3 := F(DWORD#3, LEFT(t, 2), LEFT(t, 1) < 'b');
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.r1"), 1031);
    EXPECT_EQ(run.get<std::int32_t>("Main.r2"), 2050);
    EXPECT_EQ(run.get<std::int32_t>("Main.r3"), 3021);
}

TEST(CallArguments, NestedUserCallsAndStringFunctionsInEveryPosition) {
    StProgram run(std::string(kWordStringBool) + R"(
FUNCTION G : DWORD
  VAR_INPUT x : DINT; END_VAR
  G := DINT_TO_DWORD(x + 1);
END_FUNCTION

PROGRAM Main
VAR t : STRING := 'abc'; r1, r2, r3, r4 : DINT; END_VAR
r1 := F(G(3), t, F(1, t, TRUE) = 1031);
r2 := F(G(F(0, 'xy', FALSE)), CONCAT(t, t), MID(t, 2, 2) = 'bc');
r3 := F(DINT_TO_DWORD(LEN(t)), DINT_TO_STRING(F(0, t, FALSE)), G(1) = 2);
r4 := F(5, t, F(G(2), CONCAT('a', t), t > 'abb') = 3041);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.r1"), 4031);
    EXPECT_EQ(run.get<std::int32_t>("Main.r2"), 21061);
    EXPECT_EQ(run.get<std::int32_t>("Main.r3"), 3021); // '30' has two characters
    EXPECT_EQ(run.get<std::int32_t>("Main.r4"), 5031);
}

TEST(CallArguments, FbOutputsReadInArguments) {
    StProgram run(std::string(kWordStringBool) + R"(
FUNCTION_BLOCK Named
  VAR_INPUT n : DINT; END_VAR
  VAR_OUTPUT text : STRING; count : DWORD; END_VAR
  text := LEFT('abcdefgh', n);
  count := DINT_TO_DWORD(n);
END_FUNCTION_BLOCK

PROGRAM Main
VAR fb : Named; r1, r2 : DINT; END_VAR
fb(n := 4);
r1 := F(fb.count, fb.text, fb.text = 'abcd');
r2 := F(fb.count + 1, CONCAT(fb.text, 'x'), LEN(fb.text) = 4);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.r1"), 4041);
    EXPECT_EQ(run.get<std::int32_t>("Main.r2"), 5051);
}

// Seven inputs of six widths, each computed through a host function or a nested call, in a
// function too long to be inlined and in one that is inlined.
TEST(CallArguments, ManyArgumentsOfMixedWidthsInlinedOrNot) {
    StProgram run(R"(
FUNCTION Long : LREAL
  VAR_INPUT a : SINT; b : LREAL; c : STRING[10]; d : LINT; e : BOOL; f : WORD; g : TIME; END_VAR
  VAR i : INT; acc : LREAL; END_VAR
  FOR i := 1 TO 3 DO
    acc := acc + SINT_TO_LREAL(a) + b + INT_TO_LREAL(LEN(c)) + LINT_TO_LREAL(d);
  END_FOR;
  Long := acc / 3.0 + 1000.0 * BOOL_TO_LREAL(e) + 10000.0 * WORD_TO_LREAL(f)
        + 100000.0 * LINT_TO_LREAL(TIME_TO_LINT(g));
END_FUNCTION

FUNCTION Short : LREAL
  VAR_INPUT a : SINT; b : LREAL; c : STRING[10]; d : LINT; e : BOOL; f : WORD; g : TIME; END_VAR
  Short := SINT_TO_LREAL(a) + b + INT_TO_LREAL(LEN(c)) + LINT_TO_LREAL(d)
         + 1000.0 * BOOL_TO_LREAL(e) + 10000.0 * WORD_TO_LREAL(f)
         + 100000.0 * LINT_TO_LREAL(TIME_TO_LINT(g));
END_FUNCTION

PROGRAM Main
VAR s : STRING := 'abcd'; x : LREAL := 2.0; kept, inlined : LREAL; END_VAR
kept := Long(STRING_TO_SINT('7'), x ** 3.0, CONCAT(s, 'e'), STRING_TO_LINT('20'),
             s < 'b', DINT_TO_WORD(LEN(s)), T#1ms * LEN(CONCAT(s, s)));
inlined := Short(STRING_TO_SINT('7'), x ** 3.0, CONCAT(s, 'e'), STRING_TO_LINT('20'),
               s < 'b', DINT_TO_WORD(LEN(s)), T#1ms * LEN(CONCAT(s, s)));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(inlined_callees(run.image()), std::vector<std::string>{"Short"});
    const double expected = 7 + 8 + 5 + 20 + 1000 + 40000 + 100000 * 8; // TIME_TO_LINT: ms
    EXPECT_DOUBLE_EQ(run.get<double>("Main.kept"), expected);
    EXPECT_DOUBLE_EQ(run.get<double>("Main.inlined"), expected);
}

// EN/ENO, VAR_IN_OUT, an FB's inputs and host functions of every kind (EXPT, TIME * REAL,
// selection on strings) in the arguments of nested calls.
TEST(CallArguments, EnInOutAndFbInputsAmongHostFunctions) {
    StProgram run(R"(
FUNCTION F : DINT
  VAR_INPUT w : DWORD; s : STRING; b : BOOL; END_VAR
  VAR_IN_OUT acc : DINT; END_VAR
  acc := acc + 1;
  F := LEN(s) * 10 + BOOL_TO_DINT(b) + 1000 * DWORD_TO_DINT(w);
END_FUNCTION
FUNCTION H : DINT
  VAR_INPUT a : LREAL; t : TIME; s : STRING[5]; END_VAR
  H := LREAL_TO_DINT(a) + 100 * LINT_TO_DINT(TIME_TO_LINT(t)) + 10000 * LEN(s);
END_FUNCTION
FUNCTION_BLOCK Fb
  VAR_INPUT g : BOOL; t : STRING; n : DINT; END_VAR
  VAR_OUTPUT o : STRING; END_VAR
  o := SEL(g, t, CONCAT('Y', 'Z'));
END_FUNCTION_BLOCK
PROGRAM Main
VAR t : STRING := 'abc'; acc : DINT; r1, r2, r3, r4, r5 : DINT; ok : BOOL; fb : Fb; x : LREAL := 3.0; END_VAR
r1 := F(DWORD#1, SEL(t = 'abc', 'x', CONCAT(t, t)), MAX(t, 'abd') = 'abd', acc);
r2 := F(EN := TRUE, w := 2, s := t, b := LEFT(t, 1) = 'a', acc := acc, ENO => ok);
r3 := H(x ** 2.0, T#1ms * 2.5, MID(t, 2, 2));
fb(g := t = 'abc', t := CONCAT(t, 'd'), n := F(3, t, t < 'b', acc));
r4 := F(DINT_TO_DWORD(H(x ** 2.0, T#2ms, 'ab')), CONCAT(t, 'x', t), F(1, t, t <> 'abc', acc) = 1030, acc);
r5 := fb.n;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.r1"), 1061);
    EXPECT_EQ(run.get<std::int32_t>("Main.r2"), 2031);
    EXPECT_EQ(run.get<std::int32_t>("Main.r3"), 9 + 200 + 20000);
    EXPECT_EQ(run.get<std::int32_t>("Main.r5"), 3031);
    EXPECT_EQ(run.get_string("Main.fb.o"), "YZ");
    EXPECT_EQ(run.get<std::int32_t>("Main.r4"), (9 + 200 + 20000) * 1000 + 70 + 1);
    EXPECT_EQ(run.get<std::int32_t>("Main.acc"), 5);
}

// An output is copied out of the callee's frame before the place it goes to is computed,
// which may itself call.
TEST(CallArguments, OutputsSurviveCallsInTheirTargets) {
    StProgram run(R"(
FUNCTION Pair : DINT
  VAR_INPUT x : DINT; END_VAR
  VAR_OUTPUT first, second : DINT; END_VAR
  first := x + 1;
  second := x + 2;
  Pair := x;
END_FUNCTION

FUNCTION One : DINT
  VAR_INPUT x : DINT; END_VAR
  One := x - x + 1;
END_FUNCTION

PROGRAM Main
VAR a : ARRAY[1..3] OF DINT; s : STRING := 'ab'; r, second, a1, a2, a3 : DINT; END_VAR
r := Pair(10, first => a[One(50)], second => second);
r := Pair(20, first => a[LEN(s)], second => a[LEN(CONCAT(s, 'c'))]);
a1 := a[1];
a2 := a[2];
a3 := a[3];
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.a1"), 11);
    EXPECT_EQ(run.get<std::int32_t>("Main.second"), 12);
    EXPECT_EQ(run.get<std::int32_t>("Main.a2"), 21);
    EXPECT_EQ(run.get<std::int32_t>("Main.a3"), 22);
    EXPECT_EQ(run.get<std::int32_t>("Main.r"), 20);
}

} // namespace
} // namespace eposp::compiler::test
