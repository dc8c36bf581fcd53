// IF c THEN x := a; ELSE x := b; END_IF with cheap values that cannot trap becomes a conditional
// move (CMov): the same results on both paths, including where the condition or a value reads
// the variable being assigned, and never where evaluating a value the IF would skip could trap
// or act.
#include "codegen_harness.hpp"

#include <algorithm>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

struct SelectCase {
    std::string name;
    std::string declarations; // Main also has `x : DINT;`
    std::string body;
    std::int32_t expected; // of x
    bool select;           // compiled to a CMov
};

bool has_select(const vm::Image& image) {
    return std::any_of(image.code.begin(), image.code.end(), [](const vm::Instruction& ins) {
        const auto name = vm::opcode_info(ins.opcode).name;
        return name.starts_with("CMov");
    });
}

class IfConversion : public testing::TestWithParam<SelectCase> {};

TEST_P(IfConversion, GivesTheResultOfTheBranches) {
    const SelectCase& c = GetParam();
    StProgram run("PROGRAM Main\nVAR x : DINT; " + c.declarations + " END_VAR\n" + c.body +
                  "\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(has_select(run.image()), c.select);
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Statements, IfConversion,
    testing::Values(
        SelectCase{"ThenTaken", "a : DINT := 3;",
                   "IF a > 2 THEN x := a * 2; ELSE x := a - 1; END_IF;", 6, true},
        SelectCase{"ElseTaken", "a : DINT := 1;",
                   "IF a > 2 THEN x := a * 2; ELSE x := a - 1; END_IF;", 0, true},
        SelectCase{"WithoutElseTaken", "a : DINT := -4;", "x := a; IF x < 0 THEN x := -x; END_IF;",
                   4, true},
        SelectCase{"WithoutElseSkipped", "a : DINT := 4;", "x := a; IF x < 0 THEN x := -x; END_IF;",
                   4, true},
        // The chosen value reads x, which the ELSE value has overwritten by then.
        SelectCase{"ChosenValueIsTheTarget", "c : BOOL := TRUE;",
                   "x := 9; IF c THEN x := x; ELSE x := 5; END_IF;", 9, true},
        SelectCase{"ChosenValueReadsTheTarget", "c : BOOL := TRUE;",
                   "x := 9; IF c THEN x := x + 1; ELSE x := 0; END_IF;", 10, true},
        // The condition is the variable assigned.
        SelectCase{"ConditionIsTheTarget", "f : BOOL := TRUE;",
                   "IF f THEN f := FALSE; ELSE f := TRUE; END_IF; IF f THEN x := 1; END_IF;", 0,
                   true},
        SelectCase{"BitTestOnIntegers", "a : SINT := -128; b : INT := 16#100;",
                   "IF (a AND b) <> 0 THEN x := 1; ELSE x := 2; END_IF;", 1, true},
        SelectCase{"Shifts", "w : DWORD := 16#81;",
                   "IF (w AND 1) <> 0 THEN w := SHR(w, 1) XOR 16#EDB88320; ELSE w := SHR(w, 1); "
                   "END_IF; x := DWORD_TO_DINT(w AND 16#7FFFFFFF);",
                   0x6DB88360, true},
        SelectCase{"RealTarget", "r : LREAL := -2.5;",
                   "IF r < 0.0 THEN r := -r; END_IF; x := LREAL_TO_DINT(r * 10.0);", 25, true},
        // What a skipped branch would not have done must not happen.
        SelectCase{"IndexOnlyWhenInRange", "i : INT := 11; a : ARRAY[1..10] OF DINT;",
                   "IF i <= 10 THEN x := a[i]; ELSE x := -1; END_IF;", -1, false},
        SelectCase{"ShortCircuitGuardsAnIndex", "i : INT := 11; a : ARRAY[1..10] OF DINT;",
                   "IF i <= 10 AND a[i] = 0 THEN x := 1; ELSE x := 2; END_IF;", 2, false},
        SelectCase{"DivisionOnlyWhenNonZero", "d : DINT;",
                   "IF d <> 0 THEN x := 100 / d; ELSE x := 7; END_IF;", 7, false},
        SelectCase{"SubrangeCheckedOnlyWhenStored", "s : INT(0..20); k : INT := 99; c : BOOL;",
                   "IF c THEN s := k; ELSE s := 3; END_IF; x := s;", 3, false},
        SelectCase{"TwoStatementsBranch", "a : DINT := 3; b : DINT;",
                   "IF a > 2 THEN x := 1; b := 2; ELSE x := 3; END_IF;", 1, false},
        SelectCase{"DifferentTargetsBranch", "a : DINT := 3; b : DINT;",
                   "IF a > 2 THEN x := 1; ELSE b := 3; END_IF;", 1, false},
        SelectCase{"ElsifBranches", "a : DINT := 3;",
                   "IF a > 5 THEN x := 1; ELSIF a > 2 THEN x := 2; ELSE x := 3; END_IF;", 2,
                   false}),
    [](const auto& param_info) { return param_info.param.name; });

TEST(IfConversion, CallsStayInTheirBranch) {
    StProgram run(R"(
FUNCTION Count : DINT
  VAR_IN_OUT n : DINT; END_VAR
  n := n + 1;
  Count := n;
END_FUNCTION
PROGRAM Main
  VAR x : DINT; calls : DINT; c : BOOL; END_VAR
  IF c THEN x := Count(calls); ELSE x := 4; END_IF;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.calls"), 0);
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), 4);
}

TEST(IfConversion, InOutAndFunctionResultKeepTheirBranches) {
    StProgram run(R"(
FUNCTION Pick : DINT
  VAR_INPUT c : BOOL; END_VAR
  VAR_IN_OUT v : DINT; END_VAR
  IF c THEN v := 1; ELSE v := 2; END_IF;
  IF c THEN Pick := 10; ELSE Pick := 20; END_IF;
END_FUNCTION
PROGRAM Main
  VAR x : DINT; y : DINT; END_VAR
  x := Pick(TRUE, y);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(has_select(run.image()));
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), 10);
    EXPECT_EQ(run.get<std::int32_t>("Main.y"), 1);
}

TEST(IfConversion, GlobalTarget) {
    StProgram run(R"(
PROGRAM Main
  VAR_EXTERNAL g : INT; END_VAR
  VAR c : BOOL := TRUE; END_VAR
  IF c THEN g := g + 2; ELSE g := 0; END_IF;
END_PROGRAM
CONFIGURATION Config0
  VAR_GLOBAL g : INT := 5; END_VAR
  RESOURCE Res0 ON PLC
    TASK T(INTERVAL := T#1ms, PRIORITY := 1);
    PROGRAM Inst0 WITH T : Main;
  END_RESOURCE
END_CONFIGURATION
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_TRUE(has_select(run.image()));
    ASSERT_TRUE(run.scans(2)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Config0.g"), 9);
}

} // namespace
} // namespace eposp::compiler::test
