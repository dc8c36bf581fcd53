// A PROGRAM called by its name from another POU, and its variables reached as `P.x` (the CODESYS
// extension, docs/st-language.md "Calling a PROGRAM"): the call runs the single instance of the
// program, the configuration's or one created for the calls, whose state persists.
#include "codegen_harness.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

using testing::HasSubstr;

// Counts its calls; Count grows by Step per call.
constexpr const char* kCounter = R"(
PROGRAM Counter
VAR_INPUT Step : DINT := 1; END_VAR
VAR_OUTPUT Count : DINT; END_VAR
VAR calls : DINT; END_VAR
VAR CONSTANT Limit : DINT := 1000; END_VAR
calls := calls + 1;
Count := Count + Step;
END_PROGRAM
)";

std::string with_counter(const std::string& rest) {
    return kCounter + rest;
}

TEST(CallingProgramsByName, FromAFunctionBlockAndAnotherProgramTheStateIsKept) {
    StProgram program(with_counter(R"(
FUNCTION_BLOCK Driver
VAR_OUTPUT seen : DINT; END_VAR
Counter(Step := 10);
seen := Counter.Count;
END_FUNCTION_BLOCK
PROGRAM Main
VAR d : Driver; a : DINT; b : DINT; c : DINT; END_VAR
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
)"));
    ASSERT_TRUE(program.ok()) << program.errors();
    ASSERT_TRUE(program.scans(3));
    EXPECT_EQ(program.get<std::int32_t>("Inst.a"), 23);
    EXPECT_EQ(program.get<std::int32_t>("Inst.b"), 33);
    EXPECT_EQ(program.get<std::int32_t>("Inst.c"), 6);
    // The implicit instance is watched by the program's name.
    EXPECT_EQ(program.get<std::int32_t>("Counter.Count"), 33);
    EXPECT_EQ(program.get<std::int32_t>("Counter.calls"), 6);
}

TEST(CallingProgramsByName, ACallReachesTheConfigurationsInstanceOfTheProgram) {
    // The task runs Cnt after Main has called it: two calls per scan on one state.
    StProgram program(with_counter(R"(
PROGRAM Main
VAR a : DINT; END_VAR
Counter(Step := 1);
a := Counter.Count;
END_PROGRAM
CONFIGURATION Cell RESOURCE R ON PLC
  TASK T(INTERVAL := T#10ms, PRIORITY := 1);
  PROGRAM Inst WITH T : Main;
  PROGRAM Cnt WITH T : Counter;
END_RESOURCE END_CONFIGURATION
)"));
    ASSERT_TRUE(program.ok()) << program.errors();
    ASSERT_TRUE(program.scans(4));
    EXPECT_EQ(program.get<std::int32_t>("Inst.a"), 7);
    EXPECT_EQ(program.get<std::int32_t>("Cnt.Count"), 8);
    EXPECT_EQ(program.get<std::int32_t>("Cnt.calls"), 8);
}

TEST(CallingProgramsByName, WithoutAConfigurationTheCallsReachTheDefaultInstance) {
    // Without a CONFIGURATION every PROGRAM has its own task and instance; Main's is task 0.
    StProgram program(R"(
PROGRAM Main
VAR a : DINT; END_VAR
Counter(Step := 2);
a := Counter.Count;
END_PROGRAM
)" + std::string(kCounter));
    ASSERT_TRUE(program.ok()) << program.errors();
    ASSERT_TRUE(program.scans(3));
    EXPECT_EQ(program.get<std::int32_t>("Main.a"), 6);
    EXPECT_EQ(program.get<std::int32_t>("Counter.Count"), 6);
}

TEST(CallingProgramsByName, ItsVariablesAreReadAndWrittenByName) {
    StProgram program(with_counter(R"(
PROGRAM Main
VAR before : DINT; after : DINT; limit : DINT; step : DINT; out : DINT; END_VAR
Counter.calls := 100;
Counter.Count := 5;
before := Counter.calls;
Counter(Count => out);
after := Counter.Count * 1000 + Counter.calls;
limit := Counter.Limit;
step := Counter.Step;
END_PROGRAM
CONFIGURATION Cell RESOURCE R ON PLC
  TASK T(INTERVAL := T#10ms, PRIORITY := 1);
  PROGRAM Inst WITH T : Main;
END_RESOURCE END_CONFIGURATION
)"));
    ASSERT_TRUE(program.ok()) << program.errors();
    ASSERT_TRUE(program.scans(1));
    EXPECT_EQ(program.get<std::int32_t>("Inst.before"), 100);
    EXPECT_EQ(program.get<std::int32_t>("Inst.after"), 6101);
    EXPECT_EQ(program.get<std::int32_t>("Inst.limit"), 1000);
    EXPECT_EQ(program.get<std::int32_t>("Inst.step"), 1);
    EXPECT_EQ(program.get<std::int32_t>("Inst.out"), 6);
}

TEST(CallingProgramsByName, AFunctionCallsAProgramToo) {
    StProgram program(with_counter(R"(
FUNCTION Twice : DINT
VAR_INPUT step : DINT; END_VAR
Counter(Step := step);
Counter(Step := step);
Twice := Counter.Count;
END_FUNCTION
PROGRAM Main
VAR a : DINT; END_VAR
a := Twice(3);
END_PROGRAM
CONFIGURATION Cell RESOURCE R ON PLC
  TASK T(INTERVAL := T#10ms, PRIORITY := 1);
  PROGRAM Inst WITH T : Main;
END_RESOURCE END_CONFIGURATION
)"));
    ASSERT_TRUE(program.ok()) << program.errors();
    ASSERT_TRUE(program.scans(2));
    EXPECT_EQ(program.get<std::int32_t>("Inst.a"), 12);
}

TEST(CallingProgramsByName, TwoConfigurationInstancesAreAnErrorNamingThem) {
    EXPECT_THAT(diagnostics_of(with_counter(R"(
PROGRAM Main Counter(); END_PROGRAM
CONFIGURATION Cell RESOURCE R ON PLC
  TASK T(INTERVAL := T#10ms, PRIORITY := 1);
  PROGRAM Inst WITH T : Main;
  PROGRAM Left WITH T : Counter;
  PROGRAM Right WITH T : Counter;
END_RESOURCE END_CONFIGURATION
)")),
                HasSubstr("'Counter' has several instances in the configuration (Left, Right)"));
}

TEST(CallingProgramsByName, AConstantIsNotWritten) {
    EXPECT_THAT(diagnostics_of(with_counter("PROGRAM Main Counter.Limit := 3; END_PROGRAM")),
                HasSubstr("error: this variable cannot be assigned here (a constant"));
}

TEST(CallingProgramsByName, AnUnknownMemberIsAnError) {
    EXPECT_THAT(diagnostics_of(with_counter(
                    "PROGRAM Main VAR x : DINT; END_VAR x := Counter.Nothing; END_PROGRAM")),
                HasSubstr("'Counter' has no member 'Nothing'"));
    EXPECT_THAT(diagnostics_of(with_counter("PROGRAM Main Counter(Nothing := 1); END_PROGRAM")),
                HasSubstr("'Counter' has no parameter 'Nothing'"));
}

TEST(CallingProgramsByName, AProgramCallingItselfIsRecursion) {
    EXPECT_THAT(diagnostics_of("PROGRAM Main Main(); END_PROGRAM"),
                HasSubstr("recursion is not allowed"));
    EXPECT_THAT(diagnostics_of(R"(
PROGRAM A B(); END_PROGRAM
FUNCTION_BLOCK Via A(); END_FUNCTION_BLOCK
PROGRAM B VAR v : Via; END_VAR v(); END_PROGRAM
)"),
                HasSubstr("recursion is not allowed"));
}

} // namespace
} // namespace eposp::compiler::test
