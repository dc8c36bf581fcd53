// Name resolution: every identifier of a program bound to its declaration, across files, and
// the errors a PLC programmer meets when a name is missing or taken twice.
#include "resolve_helpers.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler {
namespace {

using sema::SymbolKind;
using test::resolve_files;
using test::resolve_text;
using testing::ElementsAre;
using testing::HasSubstr;

TEST(Resolver, LocalVariableUseBindsToItsDeclaration) {
    const auto resolved = resolve_text("PROGRAM P\nVAR_INPUT x : INT; END_VAR\nVAR y : INT; "
                                       "END_VAR\ny := x;\nEND_PROGRAM\n");
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* target = resolved->assignment_target(0);
    ASSERT_NE(target, nullptr);
    EXPECT_EQ(target->kind, SymbolKind::Variable);
    EXPECT_EQ(target->section, ast::VarSectionKind::Var);
    const sema::Symbol* value = resolved->assignment_value(0);
    ASSERT_NE(value, nullptr);
    EXPECT_EQ(value->section, ast::VarSectionKind::Input);
    EXPECT_EQ(value->variable->names.front().name, "x");
}

TEST(Resolver, NamesIgnoreCase) {
    const auto resolved =
        resolve_text("PROGRAM P\nVAR Speed : INT; END_VAR\nSPEED := speed;\nEND_PROGRAM\n");
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    EXPECT_EQ(resolved->assignment_target(0), resolved->assignment_value(0));
}

TEST(Resolver, UndeclaredIdentifierIsReportedAtItsUse) {
    const auto resolved =
        resolve_text("PROGRAM P\nVAR x : INT; END_VAR\nx := speed + 1;\nEND_PROGRAM\n");
    EXPECT_EQ(resolved->rendered(), "test.st:3:6: error: undeclared identifier 'speed' [E0201]\n"
                                    "x := speed + 1;\n"
                                    "     ^~~~~\n");
}

TEST(Resolver, UndeclaredForVariableIsReported) {
    const auto resolved = resolve_text("PROGRAM P\nFOR i := 1 TO 10 DO\nEND_FOR;\nEND_PROGRAM\n");
    EXPECT_THAT(resolved->messages(), ElementsAre("undeclared identifier 'i'"));
}

TEST(Resolver, UnknownTypeIsReported) {
    const auto resolved = resolve_text("PROGRAM P\nVAR m : Motor; END_VAR\nEND_PROGRAM\n");
    EXPECT_THAT(resolved->messages(), ElementsAre("unknown type 'Motor'"));
}

TEST(Resolver, VariableUsedAsTypeIsReported) {
    const auto resolved = resolve_text("PROGRAM P\nVAR m : P; END_VAR\nEND_PROGRAM\n");
    EXPECT_THAT(resolved->messages(), ElementsAre("'P' is not a type"));
}

TEST(Resolver, DuplicateVariableNotesTheFirstDeclaration) {
    const auto resolved =
        resolve_text("PROGRAM P\nVAR x : INT; END_VAR\nVAR_INPUT x : BOOL; END_VAR\nEND_PROGRAM\n");
    EXPECT_EQ(resolved->rendered(),
              "test.st:3:11: error: 'x' is already declared in this scope [E0202]\n"
              "VAR_INPUT x : BOOL; END_VAR\n"
              "          ^\n"
              "test.st:2:5: note: 'x' was first declared here\n"
              "VAR x : INT; END_VAR\n"
              "    ^\n");
}

TEST(Resolver, SameNameInDifferentPousIsAllowed) {
    const auto resolved =
        resolve_text("FUNCTION_BLOCK A\nVAR x : INT; END_VAR\nEND_FUNCTION_BLOCK\n"
                     "FUNCTION_BLOCK B\nVAR x : INT; END_VAR\nEND_FUNCTION_BLOCK\n");
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
}

TEST(Resolver, DuplicatePouAcrossFilesPointsAtTheOtherFile) {
    const auto resolved = resolve_files({{"a.st", "FUNCTION_BLOCK Axis\nEND_FUNCTION_BLOCK\n"},
                                         {"b.st", "TYPE Axis : INT; END_TYPE\n"}});
    const std::string rendered = resolved->rendered();
    EXPECT_THAT(rendered, HasSubstr("b.st:1:6: error: 'Axis' is already declared in this scope"));
    EXPECT_THAT(rendered, HasSubstr("a.st:1:16: note: 'Axis' was first declared here"));
}

TEST(Resolver, StandardLibraryNameCannotBeRedeclared) {
    const auto resolved = resolve_text("FUNCTION_BLOCK TON\nEND_FUNCTION_BLOCK\n");
    EXPECT_THAT(resolved->messages(),
                ElementsAre("'TON' is already declared by the standard library"));
}

constexpr const char* kConfiguration = "CONFIGURATION C\n"
                                       "VAR_GLOBAL total : DINT; END_VAR\n"
                                       "RESOURCE R ON PLC\n"
                                       "TASK Cyclic (INTERVAL := T#1ms, PRIORITY := 1);\n"
                                       "PROGRAM main WITH Cyclic : Main;\n"
                                       "END_RESOURCE\n"
                                       "END_CONFIGURATION\n";

TEST(Resolver, VarExternalBindsToTheGlobalOfAnotherFile) {
    const auto resolved = resolve_files(
        {{"main.st", "PROGRAM Main\nVAR_EXTERNAL total : DINT; END_VAR\ntotal := total + 1;\n"
                     "END_PROGRAM\n"},
         {"config.st", kConfiguration}});
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* external = resolved->assignment_target(0);
    ASSERT_NE(external, nullptr);
    EXPECT_EQ(external->section, ast::VarSectionKind::External);
    const auto& declaration = std::get<ast::VarSection>(resolved->units[0].pous[0].sections[0]);
    const sema::Symbol* global = resolved->model.resolved(declaration.variables[0].names[0]);
    ASSERT_NE(global, nullptr);
    EXPECT_EQ(global->section, ast::VarSectionKind::Global);
}

TEST(Resolver, VarExternalWithoutGlobalIsReported) {
    const auto resolved = resolve_files(
        {{"main.st", "PROGRAM Main\nVAR_EXTERNAL count : DINT; END_VAR\nEND_PROGRAM\n"},
         {"config.st", kConfiguration}});
    EXPECT_THAT(resolved->messages(),
                ElementsAre("VAR_EXTERNAL 'count' has no matching VAR_GLOBAL"));
}

TEST(Resolver, ProgramInstanceNamesUnknownTaskAndType) {
    const auto resolved = resolve_text("PROGRAM Main\nEND_PROGRAM\n"
                                       "FUNCTION_BLOCK Fb\nEND_FUNCTION_BLOCK\n"
                                       "CONFIGURATION C\nRESOURCE R ON PLC\n"
                                       "TASK Fast (INTERVAL := T#1ms, PRIORITY := 1);\n"
                                       "PROGRAM a WITH Slow : Main;\n"
                                       "PROGRAM b WITH Fast : Mian;\n"
                                       "PROGRAM c WITH Fast : Fb;\n"
                                       "END_RESOURCE\nEND_CONFIGURATION\n");
    EXPECT_THAT(
        resolved->messages(),
        ElementsAre("unknown task 'Slow'", "unknown program type 'Mian'", "'Fb' is not a PROGRAM"));
}

constexpr const char* kColors = "TYPE Color : (Red, Green, Blue); END_TYPE\n";

TEST(Resolver, QualifiedAndUnqualifiedEnumValuesBindToTheValue) {
    const auto resolved = resolve_files(
        {{"main.st", "PROGRAM P\nVAR c : Color := Red; END_VAR\nc := Color#Green;\nc := Blue;\n"
                     "END_PROGRAM\n"},
         {"types.st", kColors}});
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* green = resolved->assignment_value(0);
    ASSERT_NE(green, nullptr);
    EXPECT_EQ(green->kind, SymbolKind::EnumValue);
    EXPECT_EQ(green->name, "Green");
    EXPECT_EQ(green->owner->name, "Color");
    const sema::Symbol* blue = resolved->assignment_value(1);
    ASSERT_NE(blue, nullptr);
    EXPECT_EQ(blue->name, "Blue");
}

TEST(Resolver, UnknownQualifiedEnumValueNamesTheType) {
    const auto resolved = resolve_files(
        {{"main.st", "PROGRAM P\nVAR c : Color; END_VAR\nc := Color#Purple;\nc := Shade#Red;\n"
                     "END_PROGRAM\n"},
         {"types.st", kColors}});
    EXPECT_THAT(resolved->messages(), ElementsAre("enumerated type 'Color' has no value 'Purple'",
                                                  "unknown type 'Shade'"));
}

TEST(Resolver, EnumValueOfTwoTypesMustBeQualified) {
    const auto resolved = resolve_text("TYPE Color : (Red, Green); END_TYPE\n"
                                       "TYPE Alarm : (Red, Off); END_TYPE\n"
                                       "PROGRAM P\nVAR c : Color; END_VAR\nc := Red;\n"
                                       "c := Alarm#Red;\nEND_PROGRAM\n");
    EXPECT_THAT(resolved->messages(),
                ElementsAre("'Red' is ambiguous: qualify it with its type, as in Color#Red"));
    EXPECT_EQ(resolved->diagnostics.all().front().notes.size(), 2u);
}

TEST(Resolver, EnumValueNamedLikeAStandardFunctionIsTheValueWhereAValueIsWanted) {
    const auto resolved = resolve_text("TYPE Step : (Idle, Move); END_TYPE\n"
                                       "PROGRAM P\nVAR s : Step; n : INT; END_VAR\n"
                                       "s := Move;\nn := MOVE(n);\nEND_PROGRAM\n");
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* value = resolved->assignment_value(0);
    ASSERT_NE(value, nullptr);
    EXPECT_EQ(value->kind, SymbolKind::EnumValue);
    EXPECT_EQ(value->owner->name, "Step");
}

TEST(Resolver, EnumValueNamedLikeAStandardFunctionInTwoTypesMustBeQualified) {
    const auto resolved = resolve_text("TYPE Step : (Idle, Move); END_TYPE\n"
                                       "TYPE Job : (Move, Wait); END_TYPE\n"
                                       "PROGRAM P\nVAR s : Step; END_VAR\ns := Move;\n"
                                       "s := Step#Move;\nEND_PROGRAM\n");
    EXPECT_THAT(resolved->messages(),
                ElementsAre("'Move' is ambiguous: qualify it with its type, as in Step#Move"));
}

constexpr const char* kStructs =
    "TYPE Point : STRUCT x : REAL; y : REAL; END_STRUCT; END_TYPE\n"
    "TYPE Segment : STRUCT a : Point; b : Point; END_STRUCT; END_TYPE\n"
    "TYPE Path : ARRAY[1..4] OF Segment; END_TYPE\n";

TEST(Resolver, MemberChainBindsEachMember) {
    const auto resolved = resolve_files(
        {{"main.st", "PROGRAM P\nVAR s : Segment; p : Path; END_VAR\ns.a.x := p[2].b.y;\n"
                     "END_PROGRAM\n"},
         {"types.st", kStructs}});
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
    const sema::Symbol* x = resolved->assignment_target(0);
    ASSERT_NE(x, nullptr);
    EXPECT_EQ(x->name, "x");
    const sema::Symbol* y = resolved->assignment_value(0);
    ASSERT_NE(y, nullptr);
    EXPECT_EQ(y->name, "y");
}

TEST(Resolver, UnknownMemberNamesTheType) {
    const auto resolved = resolve_files(
        {{"main.st", "PROGRAM P\nVAR s : Segment; n : INT; END_VAR\ns.a.z := 1.0;\nn.x := 1;\n"
                     "END_PROGRAM\n"},
         {"types.st", kStructs}});
    EXPECT_THAT(resolved->messages(),
                ElementsAre("'Point' has no member 'z'", "'INT' has no member 'x'"));
}

TEST(Resolver, StructInitializerMembersAreChecked) {
    const auto resolved = resolve_files(
        {{"main.st", "PROGRAM P\nVAR p : Point := (x := 1.0, w := 2.0); END_VAR\nEND_PROGRAM\n"},
         {"types.st", kStructs}});
    EXPECT_THAT(resolved->messages(), ElementsAre("'Point' has no member 'w'"));
}

TEST(Resolver, StandardFunctionBlockMembersAndParameters) {
    const auto resolved = resolve_text("PROGRAM P\nVAR t : TON; done : BOOL; END_VAR\n"
                                       "t(IN := TRUE, PT := T#1s);\ndone := t.Q;\n"
                                       "t(IN := TRUE, TIME := T#1s);\nEND_PROGRAM\n");
    EXPECT_THAT(resolved->messages(), ElementsAre("'TON' has no parameter 'TIME'"));
    const sema::Symbol* q = resolved->assignment_value(1);
    ASSERT_NE(q, nullptr);
    EXPECT_EQ(q->section, ast::VarSectionKind::Output);
    EXPECT_EQ(q->standard_type, "BOOL");
}

TEST(Resolver, UserFunctionCallBindsFormalParameters) {
    const auto resolved =
        resolve_text("FUNCTION Scale : REAL\nVAR_INPUT v : REAL; k : REAL; END_VAR\n"
                     "Scale := v * k;\nEND_FUNCTION\n"
                     "PROGRAM P\nVAR r : REAL; END_VAR\nr := Scale(v := 1.0, k := 2.0);\n"
                     "r := Scale(v := 1.0, gain := 2.0);\nr := INT_TO_REAL(3);\nEND_PROGRAM\n");
    EXPECT_THAT(resolved->messages(), ElementsAre("'Scale' has no parameter 'gain'"));
}

TEST(Resolver, ExtendedFunctionBlockSeesBaseMembers) {
    const auto resolved =
        resolve_text("FUNCTION_BLOCK Base\nVAR_INPUT enable : BOOL; END_VAR\nEND_FUNCTION_BLOCK\n"
                     "FUNCTION_BLOCK Derived EXTENDS Base\nVAR busy : BOOL; END_VAR\n"
                     "busy := enable;\nEND_FUNCTION_BLOCK\n"
                     "PROGRAM P\nVAR d : Derived; END_VAR\nd.enable := TRUE;\nEND_PROGRAM\n");
    EXPECT_TRUE(resolved->messages().empty()) << resolved->rendered();
}

TEST(Resolver, ExtendsUnknownOrCyclicBaseIsReported) {
    const auto resolved = resolve_text("FUNCTION_BLOCK A EXTENDS B\nEND_FUNCTION_BLOCK\n"
                                       "FUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\n"
                                       "FUNCTION_BLOCK C EXTENDS Nothing\nEND_FUNCTION_BLOCK\n");
    EXPECT_THAT(resolved->messages(),
                ElementsAre("'B' extends itself through 'A'", "unknown function block 'Nothing'"));
}

} // namespace
} // namespace eposp::compiler
