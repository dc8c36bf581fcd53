// Global variable lists as CODESYS writes them: VAR_GLOBAL at the top level of a file, its
// variables visible in every POU without VAR_EXTERNAL, its constants usable wherever a constant
// is needed, watched by the bare variable name.
#include "codegen_harness.hpp"
#include "parse_helpers.hpp"
#include "resolve_helpers.hpp"

#include <algorithm>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

using testing::ElementsAre;
using testing::HasSubstr;

TEST(GlobalVariableList, ParsesAtTheTopLevelWithItsQualifiers) {
    const Parsed parsed = parse_text("VAR_GLOBAL CONSTANT kMax : INT := 4; END_VAR\n"
                                     "VAR_GLOBAL RETAIN kept, also : DINT; END_VAR\n"
                                     "VAR_GLOBAL count : DINT; END_VAR\n"
                                     "VAR_GLOBAL PERSISTENT RETAIN total : LINT; END_VAR\n");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    ASSERT_EQ(parsed.unit.global_variable_lists.size(), 4u);
    const auto& constants = std::get<ast::VarSection>(parsed.unit.global_variable_lists[0]);
    EXPECT_TRUE(constants.constant);
    const auto& kept = std::get<ast::VarSection>(parsed.unit.global_variable_lists[1]);
    EXPECT_EQ(kept.retention, ast::Retention::Retain);
    EXPECT_EQ(kept.variables.front().names.size(), 2u);
    const auto& persistent = std::get<ast::VarSection>(parsed.unit.global_variable_lists[3]);
    EXPECT_EQ(persistent.retention, ast::Retention::Retain);
}

TEST(GlobalVariableList, OnlyVarGlobalIsAllowedOutsideAPou) {
    const Parsed parsed = parse_text("VAR x : INT; END_VAR\nPROGRAM P\nEND_PROGRAM\n"
                                     "VAR_EXTERNAL y : INT; END_VAR\n");
    EXPECT_EQ(parsed.rendered(),
              "test.st:1:1: error: only VAR_GLOBAL can be declared outside a POU or "
              "configuration [E0109]\n"
              "VAR x : INT; END_VAR\n"
              "^~~\n"
              "test.st:4:1: error: only VAR_GLOBAL can be declared outside a POU or "
              "configuration [E0109]\n"
              "VAR_EXTERNAL y : INT; END_VAR\n"
              "^~~~~~~~~~~~\n");
}

TEST(GlobalVariableList, NamesBindInAPouOfAnotherFileWithoutVarExternal) {
    const auto resolved =
        resolve_files({{"main.st", "PROGRAM Main\ncount := count + 1;\nEND_PROGRAM\n"},
                       {"gvl.st", "VAR_GLOBAL count : DINT; END_VAR\n"}});
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* target = resolved->assignment_target(0);
    ASSERT_NE(target, nullptr);
    EXPECT_EQ(target->section, ast::VarSectionKind::Global);
}

TEST(GlobalVariableList, ALocalDeclarationShadowsTheGlobal) {
    const auto resolved = resolve_text("PROGRAM Main\nVAR count : INT; END_VAR\ncount := 1;\n"
                                       "END_PROGRAM\nVAR_GLOBAL count : DINT; END_VAR\n");
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* target = resolved->assignment_target(0);
    ASSERT_NE(target, nullptr);
    EXPECT_EQ(target->section, ast::VarSectionKind::Var);
}

TEST(GlobalVariableList, ANameDeclaredInTwoListsIsAnError) {
    const auto resolved = resolve_files({{"a.st", "VAR_GLOBAL count : DINT; END_VAR\n"},
                                         {"b.st", "VAR_GLOBAL\n  count : INT;\nEND_VAR\n"}});
    const std::string rendered = resolved->rendered();
    EXPECT_THAT(rendered, HasSubstr("b.st:2:3: error: 'count' is already declared in this scope"));
    EXPECT_THAT(rendered, HasSubstr("a.st:1:12: note: 'count' was first declared here"));
}

TEST(GlobalVariableList, ANameOfAPouOrTypeIsTaken) {
    const auto resolved = resolve_text("TYPE Axis : INT; END_TYPE\nPROGRAM Main\nEND_PROGRAM\n"
                                       "VAR_GLOBAL Axis : BOOL; main : INT; END_VAR\n");
    EXPECT_THAT(resolved->messages(), ElementsAre("'Axis' is already declared in this scope",
                                                  "'main' is already declared in this scope"));
}

TEST(GlobalVariableList, AProgramInstanceCannotTakeTheNameOfAGlobal) {
    const auto resolved =
        resolve_text("VAR_GLOBAL Inst0 : INT; END_VAR\n"
                     "PROGRAM Main\nEND_PROGRAM\n"
                     "CONFIGURATION C\nTASK T(INTERVAL := T#1ms, PRIORITY := 1);\n"
                     "PROGRAM Inst0 WITH T : Main;\nEND_CONFIGURATION\n");
    EXPECT_EQ(resolved->rendered(), "test.st:6:9: error: 'Inst0' is already the name of a global "
                                    "variable [E0202]\n"
                                    "PROGRAM Inst0 WITH T : Main;\n"
                                    "        ^~~~~\n"
                                    "test.st:1:12: note: 'Inst0' was declared here\n"
                                    "VAR_GLOBAL Inst0 : INT; END_VAR\n"
                                    "           ^~~~~\n");
}

constexpr const char* kGlobals = R"(TYPE AxisIndex : INT(0..kLast); END_TYPE
VAR_GLOBAL CONSTANT
  kAxes : INT := 4;
  kLast : INT := kAxes - 1;
END_VAR
VAR_GLOBAL
  count : DINT;
  calls : DINT := kAxes * 10;
  last : AxisIndex := kLast;
END_VAR
)";

constexpr const char* kMain = R"(FUNCTION Twice : DINT
  VAR_INPUT v : DINT; END_VAR
  Twice := v * 2;
  calls := calls + 1;
END_FUNCTION
FUNCTION_BLOCK Step
  VAR_EXTERNAL count : DINT; END_VAR
  count := count + 1;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR
    axes : ARRAY[1..kAxes] OF LREAL;
    step : Step;
    i : INT;
    kind : INT;
    doubled : DINT;
  END_VAR
  step();
  FOR i := 1 TO kAxes DO axes[i] := axes[i] + 1.0; END_FOR
  CASE count OF
    kAxes: kind := 1;
  ELSE
    kind := 0;
  END_CASE
  doubled := Twice(count);
END_PROGRAM
)";

TEST(GlobalVariableList, VariablesAndConstantsServeEveryPouOfEveryFile) {
    StProgram run({{"gvl.st", kGlobals}, {"main.st", kMain}});
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(4));
    EXPECT_EQ(run.get<std::int32_t>("count"), 4);
    EXPECT_EQ(run.get<std::int32_t>("calls"), 44);
    EXPECT_EQ(run.get<std::int16_t>("last"), 3);
    EXPECT_EQ(run.get<std::int16_t>("kAxes"), 4);
    EXPECT_EQ(run.get<double>("Main.axes[4]"), 4.0);
    EXPECT_EQ(run.get<std::int16_t>("Main.kind"), 1);
    EXPECT_EQ(run.get<std::int32_t>("Main.doubled"), 8);
}

TEST(GlobalVariableList, RetainAndPersistentVariablesAreInTheRetainLayout) {
    StProgram run("VAR_GLOBAL RETAIN kept : DINT; END_VAR\nVAR_GLOBAL lost : DINT; END_VAR\n"
                  "VAR_GLOBAL PERSISTENT total : LINT; END_VAR\n"
                  "PROGRAM Main\nkept := lost;\ntotal := kept;\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    const auto offset_of = [&](const std::string& path) {
        const auto& symbols = run.image().symbols;
        const auto it = std::find_if(symbols.begin(), symbols.end(),
                                     [&](const vm::Symbol& symbol) { return symbol.path == path; });
        return it == symbols.end() ? UINT32_MAX : it->offset;
    };
    EXPECT_EQ(run.image().retain,
              (std::vector<vm::RetainRange>{{offset_of("kept"), 4}, {offset_of("total"), 8}}));
}

TEST(GlobalVariableList, AConstantCannotBeAssigned) {
    EXPECT_THAT(diagnostics_of("VAR_GLOBAL CONSTANT kMax : INT := 4; END_VAR\n"
                               "PROGRAM Main\nkMax := 5;\nEND_PROGRAM\n"),
                HasSubstr("test.st:3:1: error: this variable cannot be assigned here"));
}

// Constants of several lists may refer to each other, so a cycle must end in an error.
TEST(GlobalVariableList, AConstantDefinedThroughItselfHasNoValue) {
    const std::string errors = diagnostics_of(
        "VAR_GLOBAL CONSTANT a : INT := b; END_VAR\nVAR_GLOBAL CONSTANT b : INT := a; END_VAR\n"
        "PROGRAM Main\nVAR x : ARRAY[1..a] OF INT; END_VAR\nEND_PROGRAM\n");
    EXPECT_THAT(errors, HasSubstr("test.st:1:32: error: the constant 'a' is defined through itself"));
    EXPECT_THAT(errors, HasSubstr("test.st:4:15: error: array bounds must be constants"));
}

TEST(GlobalVariableList, AccessPathsNameItsVariablesButNotItsNames) {
    constexpr const char* kProgram = "VAR_GLOBAL total : DINT; END_VAR\n"
                                     "PROGRAM Main\ntotal := total + 1;\nEND_PROGRAM\n"
                                     "CONFIGURATION C\nVAR_ACCESS\n";
    constexpr const char* kTasks = "END_VAR\nTASK T(INTERVAL := T#1ms, PRIORITY := 1);\n"
                                   "PROGRAM Inst0 WITH T : Main;\nEND_CONFIGURATION\n";
    StProgram published(std::string(kProgram) + "  Sum : total : DINT;\n" + kTasks);
    ASSERT_TRUE(published.ok()) << published.errors();
    ASSERT_TRUE(published.scans(2));
    EXPECT_EQ(published.get<std::int32_t>("Sum"), 2);
    EXPECT_THAT(diagnostics_of(std::string(kProgram) + "  total : total : DINT;\n" + kTasks),
                HasSubstr("test.st:7:3: error: 'total' is already the name of a global variable"));
}

} // namespace
} // namespace eposp::compiler::test
