// The passes over finished code: small leaf POUs run in place of their calls (the same results,
// the callee named in run-time errors, and the calls that must stay calls), and branches inside
// loops take the loop's back-edge themselves.
#include "codegen_harness.hpp"

#include <algorithm>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

const vm::Pou& pou_named(const vm::Image& image, const std::string& name) {
    return *std::find_if(image.pous.begin(), image.pous.end(),
                         [&](const vm::Pou& pou) { return pou.name == name; });
}

std::vector<std::string> inlined_into(const vm::Image& image, const std::string& caller) {
    std::vector<std::string> names;
    for (const vm::InlinedCall& call : pou_named(image, caller).inlined) {
        names.push_back(image.pous[call.callee].name);
    }
    return names;
}

bool calls(const vm::Image& image, const std::string& caller, vm::Opcode op) {
    const vm::Pou& pou = pou_named(image, caller);
    return std::any_of(image.code.begin() + pou.code_begin, image.code.begin() + pou.code_end,
                       [&](const vm::Instruction& ins) { return ins.opcode == op; });
}

TEST(CallInlining, StandardFbsRunInPlaceAndKeepTheirState) {
    StProgram run(R"(
PROGRAM Main
VAR edge : R_TRIG; count : CTU; clk : BOOL; n : INT; END_VAR
clk := NOT clk;
edge(CLK := clk);
count(CU := edge.Q, PV := 100);
n := count.CV;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(inlined_into(run.image(), "Main"), (std::vector<std::string>{"R_TRIG", "CTU"}));
    EXPECT_FALSE(calls(run.image(), "Main", vm::Opcode::CallFb));
    ASSERT_TRUE(run.scans(6));
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 3);
}

TEST(CallInlining, EachInlinedFunctionCallHasItsOwnLocalsAndResult) {
    StProgram run(R"(
FUNCTION Bump : DINT
  VAR_INPUT x : DINT; END_VAR
  VAR k : DINT := 5; END_VAR
  k := k + x;
  Bump := k;
END_FUNCTION
PROGRAM Main
VAR r : DINT; END_VAR
r := Bump(1) * 100 + Bump(Bump(2));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(inlined_into(run.image(), "Main"),
              (std::vector<std::string>{"Bump", "Bump", "Bump"}));
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int32_t>("Main.r"), 612);
}

TEST(CallInlining, RunTimeErrorInAnInlinedFbNamesTheFbAndItsLine) {
    StProgram run(R"(
FUNCTION_BLOCK Share
  VAR_INPUT total, parts : DINT; END_VAR
  VAR_OUTPUT each : DINT; END_VAR
  each := total / parts;
END_FUNCTION_BLOCK
PROGRAM Main
VAR s : Share; END_VAR
s(total := 10, parts := 0);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_EQ(inlined_into(run.image(), "Main"), std::vector<std::string>{"Share"});
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "division by zero in Share at line 5");
}

TEST(BackEdgeDuplication, BranchesInsideALoopLoopWithoutAJump) {
    StProgram run(R"(
PROGRAM Main
VAR i, up, down : INT; END_VAR
FOR i := 1 TO 10 DO
  IF i MOD 3 = 0 THEN up := up + 1; ELSE down := down + 1; END_IF;
END_FOR;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    const vm::Image& image = run.image();
    for (const vm::Instruction& ins : image.code) {
        if (ins.opcode == vm::Opcode::Jmp) {
            EXPECT_FALSE(vm::opcode_info(image.code[ins.a].opcode).name.starts_with("For"));
        }
    }
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int16_t>("Main.up"), 3);
    EXPECT_EQ(run.get<std::int16_t>("Main.down"), 7);
    EXPECT_EQ(run.get<std::int16_t>("Main.i"), 11);
}

TEST(CallInlining, InstancesThroughReferencesAndLargeBodiesStayCalls) {
    std::string long_body;
    for (int i = 0; i < 30; ++i) {
        long_body += "  n := n + 1;\n";
    }
    StProgram run(R"(
FUNCTION_BLOCK Long
  VAR_OUTPUT n : DINT; END_VAR
)" + long_body + R"(END_FUNCTION_BLOCK
FUNCTION Pulse : BOOL
  VAR_IN_OUT edge : R_TRIG; END_VAR
  VAR_INPUT clk : BOOL; END_VAR
  edge(CLK := clk);
  Pulse := edge.Q;
END_FUNCTION
PROGRAM Main
VAR l : Long; e : R_TRIG; q : BOOL; END_VAR
l();
q := Pulse(e, TRUE);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_TRUE(calls(run.image(), "Main", vm::Opcode::CallFb));
    EXPECT_TRUE(calls(run.image(), "Pulse", vm::Opcode::CallFbP));
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int32_t>("Main.l.n"), 30);
    EXPECT_TRUE(run.get<bool>("Main.q"));
}

} // namespace
} // namespace eposp::compiler::test
