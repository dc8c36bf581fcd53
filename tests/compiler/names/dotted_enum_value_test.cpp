// Enumeration values written as CODESYS and TwinCAT do, `Color.Red`: the same as IEC's
// `Color#Red` wherever an expression may stand, unless a variable of that name hides the type.
#include "codegen_harness.hpp"
#include "resolve_helpers.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

constexpr const char* kStates = "TYPE State : (Idle := 0, Run := 10, Fault := 20); END_TYPE\n";

TEST(DottedEnumValue, BindsToTheValueOfTheType) {
    const auto resolved = resolve_files(
        {{"main.st", "PROGRAM P\nVAR s : State; END_VAR\ns := State.Run;\nEND_PROGRAM\n"},
         {"types.st", kStates}});
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* run = resolved->assignment_value(0);
    ASSERT_NE(run, nullptr);
    EXPECT_EQ(run->kind, sema::SymbolKind::EnumValue);
    EXPECT_EQ(run->owner->name, "State");
}

TEST(DottedEnumValue, AnUnknownValueNamesTheType) {
    const auto resolved =
        resolve_text(std::string(kStates) + "PROGRAM P\nVAR s : State; END_VAR\ns := State.Stop;\n"
                                            "END_PROGRAM\n");
    EXPECT_EQ(resolved->rendered(), "test.st:4:12: error: enumerated type 'State' has no value "
                                    "'Stop' [E0205]\n"
                                    "s := State.Stop;\n"
                                    "           ^~~~\n");
}

TEST(DottedEnumValue, AVariableOfTheSameNameHidesTheType) {
    const auto resolved =
        resolve_text(std::string(kStates) + "TYPE Holder : STRUCT Run : INT; END_STRUCT END_TYPE\n"
                                            "PROGRAM P\nVAR State : Holder; i : INT; END_VAR\n"
                                            "i := State.Run;\nEND_PROGRAM\n");
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* run = resolved->assignment_value(0);
    ASSERT_NE(run, nullptr);
    EXPECT_EQ(run->kind, sema::SymbolKind::Variable);
}

TEST(DottedEnumValue, ServesAsValueInitialValueCaseLabelAndBound) {
    StProgram run(std::string(kStates) + R"(
TYPE Axis :
STRUCT
  state : State := State.Fault;
END_STRUCT
END_TYPE
VAR_GLOBAL CONSTANT kStart : State := State.Run; END_VAR
PROGRAM Main
VAR
  axis : Axis;
  s : State := kStart;
  counts : ARRAY[State.Idle..State.Fault] OF INT;
  code : INT;
  window : INT(State.Idle..State.Run) := State.Run;
END_VAR
CASE s OF
  State.Idle: code := 1;
  State.Run, State.Fault: code := 2;
END_CASE
counts[State.Fault] := counts[State.Fault] + 1;
IF axis.state = State.Fault THEN s := State.Idle; END_IF
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.code"), 2);
    EXPECT_EQ(run.get<std::int16_t>("Main.s"), 0);
    EXPECT_EQ(run.get<std::int16_t>("Main.counts[20]"), 1);
    EXPECT_EQ(run.get<std::int16_t>("Main.window"), 10);
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.code"), 1);
}

TEST(DottedEnumValue, IsNotAVariable) {
    EXPECT_THAT(diagnostics_of(std::string(kStates) +
                               "PROGRAM Main\nVAR s : State; END_VAR\nState.Run := s;\n"
                               "END_PROGRAM\n"),
                testing::HasSubstr("test.st:4:1: error: 'State' is not a variable"));
}

} // namespace
} // namespace eposp::compiler::test
