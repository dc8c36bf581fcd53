// CompileOptions::substitutions: a test double stands in for a FUNCTION_BLOCK wherever the
// original is used as a type, and the original is not generated.
#include "compile_options_harness.hpp"
#include "eposp/compiler/types/front_end.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

using testing::Contains;
using testing::HasSubstr;
using testing::Not;

// The real block reports 1, its double 2. The original's body would not compile (a STRING into
// a DINT): generating it would be an error.
constexpr const char* kBlocks = R"(
FUNCTION_BLOCK Valve
VAR_INPUT open : BOOL; END_VAR
VAR_OUTPUT state : DINT; END_VAR
state := 'not a number';
END_FUNCTION_BLOCK
FUNCTION_BLOCK FakeValve
VAR_INPUT open : BOOL; END_VAR
VAR_OUTPUT state : DINT; END_VAR
state := 2;
END_FUNCTION_BLOCK
)";

// Every kind of use of Valve as a type.
constexpr const char* kUses = R"(
TYPE Line : STRUCT inlet : Valve; END_STRUCT; END_TYPE
FUNCTION_BLOCK Station
VAR v : Valve; END_VAR
VAR_OUTPUT state : DINT; END_VAR
v(open := TRUE); state := v.state;
END_FUNCTION_BLOCK
FUNCTION Drive : DINT
VAR_IN_OUT v : Valve; END_VAR
v(open := TRUE); Drive := v.state;
END_FUNCTION
PROGRAM Main
VAR
  single : Valve; many : ARRAY[0..1] OF Valve; station : Station; line : Line;
  by_ref : REF_TO Valve;
  s_single, s_many, s_station, s_line, s_in_out, s_ref : DINT;
END_VAR
single(open := TRUE); s_single := single.state;
many[1](open := TRUE); s_many := many[1].state;
station(); s_station := station.state;
line.inlet(open := TRUE); s_line := line.inlet.state;
s_in_out := Drive(v := single);
by_ref := REF(many[0]); by_ref^(open := TRUE); s_ref := by_ref^.state;
END_PROGRAM
)";

TEST(FbSubstitution, EveryUseAsATypeNamesTheDouble) {
    OptionsCompilation compilation;
    compilation.add("blocks.st", kBlocks);
    compilation.add("main.st", kUses);
    ASSERT_TRUE(compilation.compile({.substitutions = {{"Valve", "FakeValve"}}}))
        << compilation.errors();
    EXPECT_THAT(compilation.pous(), Not(Contains("Valve")));
    ASSERT_TRUE(compilation.run(1)) << compilation.errors();
    for (const char* use : {"s_single", "s_many", "s_station", "s_line", "s_in_out", "s_ref"}) {
        EXPECT_EQ(compilation.get(std::string("Main.") + use), 2) << use;
    }
}

// The original is gone from the program, so a block derived from it derives from the double.
TEST(FbSubstitution, ABlockExtendingTheOriginalExtendsTheDouble) {
    OptionsCompilation compilation;
    compilation.add("blocks.st", kBlocks);
    compilation.add("main.st", R"(
FUNCTION_BLOCK Special EXTENDS Valve
VAR_OUTPUT shown : BOOL; END_VAR
shown := open;
END_FUNCTION_BLOCK
PROGRAM Main
VAR s : Special; shown : BOOL; END_VAR
s(open := TRUE); shown := s.shown;
END_PROGRAM
)");
    ASSERT_TRUE(compilation.compile({.substitutions = {{"Valve", "FakeValve"}}}))
        << compilation.errors();
    ASSERT_TRUE(compilation.run(1)) << compilation.errors();
    EXPECT_EQ(compilation.get("Main.shown"), 1);
}

TEST(FbSubstitution, WithoutTheOptionTheOriginalIsGenerated) {
    OptionsCompilation compilation;
    compilation.add("blocks.st", kBlocks);
    compilation.add("main.st", kUses);
    ASSERT_FALSE(compilation.compile());
    EXPECT_THAT(compilation.errors(), HasSubstr("blocks.st:5:"));
}

TEST(FbSubstitution, NamesCompareCaseInsensitively) {
    OptionsCompilation compilation;
    compilation.add("blocks.st", kBlocks);
    compilation.add("main.st", kUses);
    ASSERT_TRUE(compilation.compile({.substitutions = {{"VALVE", "fakevalve"}}}))
        << compilation.errors();
}

TEST(FbSubstitution, ADoubleWithoutAnInputUsedIsTheOrdinaryErrorAtTheUse) {
    OptionsCompilation compilation;
    compilation.add("blocks.st", kBlocks);
    compilation.add("double.st", "FUNCTION_BLOCK Mute\nVAR_OUTPUT state : DINT; END_VAR\n"
                                 "END_FUNCTION_BLOCK\n");
    compilation.add("main.st", kUses);
    ASSERT_FALSE(compilation.compile({.substitutions = {{"Valve", "Mute"}}}));
    EXPECT_THAT(compilation.errors(), HasSubstr("main.st:6:3: error: 'Mute' has no parameter "
                                                "'open'"));
}

// A library's FUNCTION_BLOCK without statements is native (C++); an ST double replaces it, so
// the image no longer imports it and links without it.
TEST(FbSubstitution, AnStDoubleReplacesANativeBlock) {
    const char* library = "FUNCTION_BLOCK MC_Power\nVAR_INPUT Enable : BOOL; END_VAR\n"
                          "VAR_OUTPUT Status : BOOL; END_VAR\nEND_FUNCTION_BLOCK\n";
    const char* program = R"(
FUNCTION_BLOCK PowerDouble
VAR_INPUT Enable : BOOL; END_VAR
VAR_OUTPUT Status : BOOL; END_VAR
Status := Enable;
END_FUNCTION_BLOCK
PROGRAM Main
VAR power : MC_Power; on : BOOL; END_VAR
power(Enable := TRUE); on := power.Status;
END_PROGRAM
)";
    OptionsCompilation native;
    native.add("main.st", program);
    native.add_library("motion.st", library);
    ASSERT_TRUE(native.compile()) << native.errors();
    EXPECT_THAT(native.imports(), Contains("MC_Power"));

    OptionsCompilation doubled;
    doubled.add("main.st", program);
    doubled.add_library("motion.st", library);
    ASSERT_TRUE(doubled.compile({.substitutions = {{"MC_Power", "PowerDouble"}}}))
        << doubled.errors();
    EXPECT_THAT(doubled.imports(), Not(Contains("MC_Power")));
    ASSERT_TRUE(doubled.run(1)) << doubled.errors();
    EXPECT_EQ(doubled.get("Main.on"), 1);
}

TEST(FbSubstitution, AStandardBlockCanBeReplaced) {
    OptionsCompilation compilation;
    compilation.add("main.st", R"(
FUNCTION_BLOCK InstantTimer
VAR_INPUT IN : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
Q := IN;
END_FUNCTION_BLOCK
PROGRAM Main
VAR t : TON; done : BOOL; END_VAR
t(IN := TRUE, PT := T#1h); done := t.Q;
END_PROGRAM
)");
    ASSERT_TRUE(compilation.compile({.substitutions = {{"TON", "InstantTimer"}}}))
        << compilation.errors();
    ASSERT_TRUE(compilation.run(1)) << compilation.errors();
    EXPECT_EQ(compilation.get("Main.done"), 1);
}

TEST(FbSubstitution, AnUnknownNameOnEitherSideIsAnErrorNamingTheOption) {
    OptionsCompilation compilation;
    compilation.add("blocks.st", kBlocks);
    compilation.add("main.st", kUses);
    ASSERT_FALSE(compilation.compile({.substitutions = {{"Valv", "FakeValve"}}}));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("error: substitutions: no FUNCTION_BLOCK named 'Valv' (substituting "
                          "'Valv' by 'FakeValve')"));
    ASSERT_FALSE(compilation.compile({.substitutions = {{"Valve", "Nothing"}}}));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("error: substitutions: no FUNCTION_BLOCK named 'Nothing' "
                          "(substituting 'Valve' by 'Nothing')"));
}

TEST(FbSubstitution, OnlyAFunctionBlockCanStandInForAFunctionBlock) {
    OptionsCompilation compilation;
    compilation.add("blocks.st", kBlocks);
    compilation.add("main.st", kUses);
    ASSERT_FALSE(compilation.compile({.substitutions = {{"Valve", "Drive"}}}));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("error: substitutions: 'Drive' is a FUNCTION, not a FUNCTION_BLOCK "
                          "(substituting 'Valve' by 'Drive')"));
    ASSERT_FALSE(compilation.compile({.substitutions = {{"Main", "FakeValve"}}}));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("error: substitutions: 'Main' is a PROGRAM, not a FUNCTION_BLOCK"));
}

TEST(FbSubstitution, ADoubleCannotItselfBeSubstituted) {
    OptionsCompilation compilation;
    compilation.add("blocks.st", kBlocks);
    compilation.add("main.st", kUses);
    ASSERT_FALSE(compilation.compile({.substitutions = {{"Valve", "Valve"}}}));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("error: substitutions: 'Valve' cannot stand in for itself"));
    ASSERT_FALSE(
        compilation.compile({.substitutions = {{"Valve", "FakeValve"}, {"FakeValve", "Station"}}}));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("error: substitutions: 'FakeValve' stands in for 'Valve' and is "
                          "substituted itself"));
    ASSERT_FALSE(
        compilation.compile({.substitutions = {{"Valve", "FakeValve"}, {"VALVE", "Station"}}}));
    EXPECT_THAT(compilation.errors(), HasSubstr("error: substitutions: 'Valve' is substituted "
                                                "twice"));
}

TEST(FbSubstitution, TheFrontEndOfTheReferenceEvaluatorHonoursThem) {
    SourceManager sources;
    const std::vector<FileId> files = {sources.add("blocks.st", kBlocks),
                                       sources.add("main.st", kUses)};
    Diagnostics diagnostics;
    const auto front_end =
        types::analyse(sources, files, diagnostics, {.substitutions = {{"Valve", "FakeValve"}}});
    ASSERT_FALSE(diagnostics.has_errors()) << render(diagnostics, sources);
    ASSERT_TRUE(front_end->program);
    ASSERT_EQ(front_end->units[0].pous.size(), 1u);
    EXPECT_EQ(front_end->units[0].pous[0].name.name, "FakeValve");
}

} // namespace
} // namespace eposp::compiler::test
