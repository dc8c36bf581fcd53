// EN and ENO on standard function calls (IEC 61131-3 ed. 3, 6.6.1.2.2, table 18), compiled and
// run: with EN := FALSE the function is not executed, ENO is FALSE and the variable the result
// is assigned to keeps its value; with EN := TRUE (or without EN) the result is assigned and ENO
// is TRUE. User functions and FB instances are covered in codegen_calls_test.cpp.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

/// `y := <call>` where the call names EN := en and ENO => eno.
struct EnabledCall {
    std::string name;
    std::string y_type;
    std::string y_initial; // a literal of y_type, kept when EN is FALSE
    std::string call;
    std::string expected; // an expression of y_type: y's value when EN is TRUE
};

void PrintTo(const EnabledCall& c, std::ostream* os) {
    *os << c.call;
}

std::string program_for(const EnabledCall& c, bool en) {
    return "PROGRAM Main\nVAR\n  en : BOOL := " + std::string(en ? "TRUE" : "FALSE") +
           "; eno : BOOL := " + (en ? "FALSE" : "TRUE") + ";\n  y : " + c.y_type +
           " := " + c.y_initial +
           ";\n  a : INT := 7; b : INT := 3; r : REAL := 2.0; s : STRING := 'abcdef';\n"
           "  w : WSTRING := \"abcdef\"; t : TIME := T#1s;\n"
           "  ran, kept : BOOL;\nEND_VAR\n" +
           "y := " + c.call + ";\nran := y = " + c.expected + ";\nkept := y = " + c.y_initial +
           ";\nEND_PROGRAM\n";
}

class StandardFunctionWithEn : public testing::TestWithParam<EnabledCall> {};

TEST_P(StandardFunctionWithEn, EnFalseSkipsItAndKeepsTheResultVariable) {
    StProgram run(program_for(GetParam(), false));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_TRUE(run.get<bool>("Main.kept"));
    EXPECT_FALSE(run.get<bool>("Main.eno"));
}

TEST_P(StandardFunctionWithEn, EnTrueRunsItAndSetsEno) {
    StProgram run(program_for(GetParam(), true));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_TRUE(run.get<bool>("Main.ran"));
    EXPECT_TRUE(run.get<bool>("Main.eno"));
}

INSTANTIATE_TEST_SUITE_P(
    EveryGroup, StandardFunctionWithEn,
    testing::Values(
        EnabledCall{"Add", "INT", "-1", "ADD(EN := en, IN1 := a, IN2 := b, ENO => eno)", "10"},
        EnabledCall{"AddExtensible", "INT", "-1",
                    "ADD(EN := en, IN1 := a, IN2 := b, IN3 := 1, ENO => eno)", "11"},
        EnabledCall{"Sub", "INT", "-1", "SUB(EN := en, IN1 := a, IN2 := b, ENO => eno)", "4"},
        EnabledCall{"Mul", "INT", "-1", "MUL(EN := en, IN1 := a, IN2 := b, ENO => eno)", "21"},
        EnabledCall{"Div", "INT", "-1", "DIV(EN := en, IN1 := a, IN2 := b, ENO => eno)", "2"},
        EnabledCall{"Abs", "INT", "-1", "ABS(EN := en, IN := -a, ENO => eno)", "7"},
        EnabledCall{"Sqrt", "REAL", "-1.0", "SQRT(EN := en, IN := REAL#16.0, ENO => eno)", "4.0"},
        EnabledCall{"Expt", "REAL", "-1.0", "EXPT(EN := en, IN1 := r, IN2 := 3, ENO => eno)",
                    "8.0"},
        EnabledCall{"Limit", "INT", "-1", "LIMIT(EN := en, MN := 0, IN := a, MX := 5, ENO => eno)",
                    "5"},
        EnabledCall{"Max", "INT", "-1", "MAX(EN := en, IN1 := a, IN2 := b, ENO => eno)", "7"},
        EnabledCall{"Min", "INT", "-1", "MIN(EN := en, IN1 := a, IN2 := b, ENO => eno)", "3"},
        EnabledCall{"Sel", "INT", "-1", "SEL(EN := en, G := TRUE, IN0 := a, IN1 := b, ENO => eno)",
                    "3"},
        EnabledCall{"Mux", "INT", "-1", "MUX(EN := en, K := 0, IN0 := a, IN1 := b, ENO => eno)",
                    "7"},
        EnabledCall{"Move", "INT", "-1", "MOVE(EN := en, IN := a, ENO => eno)", "7"},
        EnabledCall{"Shl", "WORD", "WORD#16#FFFF",
                    "SHL(EN := en, IN := WORD#1, N := 4, ENO => eno)", "WORD#16"},
        EnabledCall{"Gt", "BOOL", "FALSE", "GT(EN := en, IN1 := a, IN2 := b, ENO => eno)", "TRUE"},
        EnabledCall{"IntToReal", "REAL", "-1.0", "INT_TO_REAL(EN := en, IN := a, ENO => eno)",
                    "7.0"},
        EnabledCall{"ToDint", "DINT", "-1", "TO_DINT(EN := en, IN := a, ENO => eno)", "7"},
        EnabledCall{"Trunc", "DINT", "-1", "TRUNC(EN := en, IN := REAL#2.5, ENO => eno)", "2"},
        EnabledCall{"IntToString", "STRING", "'old'",
                    "INT_TO_STRING(EN := en, IN := a, ENO => eno)", "'7'"},
        EnabledCall{"Concat", "STRING", "'old'",
                    "CONCAT(EN := en, IN1 := 'x', IN2 := s, ENO => eno)", "'xabcdef'"},
        EnabledCall{"Left", "STRING", "'old'", "LEFT(EN := en, IN := s, L := 2, ENO => eno)",
                    "'ab'"},
        EnabledCall{"Mid", "STRING", "'old'", "MID(EN := en, IN := s, L := 2, P := 3, ENO => eno)",
                    "'cd'"},
        EnabledCall{"Len", "INT", "-1", "LEN(EN := en, IN := s, ENO => eno)", "6"},
        EnabledCall{"Find", "INT", "-1", "FIND(EN := en, IN1 := s, IN2 := 'cd', ENO => eno)", "3"},
        EnabledCall{"WstringReplace", "WSTRING", "\"old\"",
                    "REPLACE(EN := en, IN1 := w, IN2 := \"XY\", L := 1, P := 2, ENO => eno)",
                    "\"aXYcdef\""},
        EnabledCall{"AddTime", "TIME", "T#0s",
                    "ADD_TIME(EN := en, IN1 := t, IN2 := T#500ms, ENO => eno)", "T#1500ms"}),
    [](const auto& c) { return c.param.name; });

TEST(EnableOnStandardFunctions, WithoutEnEnoIsTrue) {
    StProgram run(R"(
PROGRAM Main
VAR ok : BOOL; y : DINT; END_VAR
y := ADD(IN1 := 1, IN2 := 2, ENO => ok);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.y"), 3);
    EXPECT_TRUE(run.get<bool>("Main.ok"));
}

TEST(EnableOnStandardFunctions, AnArrayElementAssignedFromASkippedCallKeepsItsValue) {
    StProgram run(R"(
PROGRAM Main
VAR v : ARRAY[1..3] OF INT := [1, 2, 3]; i : INT := 2; off : BOOL; END_VAR
v[i] := MUL(EN := off, IN1 := i, IN2 := 10);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.v[2]"), 2);
}

TEST(EnableOnStandardFunctions, InsideAnExpressionASkippedCallGivesZeroOrAnEmptyString) {
    StProgram run(R"(
PROGRAM Main
VAR n : INT := -1; s : STRING := 'old'; off : BOOL; END_VAR
n := ADD(EN := off, IN1 := 1, IN2 := 1) + 10;
s := CONCAT(LEFT(EN := off, IN := 'abc', L := 2), 'x');
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 10);
    EXPECT_EQ(run.get_string("Main.s"), "x");
}

TEST(EnableOnStandardFunctions, EnIsEvaluatedEveryScan) {
    StProgram run(R"(
PROGRAM Main
VAR n : DINT; scans : DINT; ok : BOOL; END_VAR
scans := scans + 1;
n := ADD(EN := scans MOD 2 = 0, IN1 := n, IN2 := 1, ENO => ok);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(3)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.n"), 1);
    EXPECT_FALSE(run.get<bool>("Main.ok"));
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.n"), 2);
    EXPECT_TRUE(run.get<bool>("Main.ok"));
}

} // namespace
} // namespace eposp::compiler::test
