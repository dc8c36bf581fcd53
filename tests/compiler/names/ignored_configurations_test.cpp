// CompileOptions::ignored_configurations: the test harness brings its own CONFIGURATION and the
// user's is dropped whole, while the user's POUs, types and global variable lists stay.
#include "compile_options_harness.hpp"
#include "eposp/compiler/types/front_end.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

using testing::Contains;
using testing::HasSubstr;
using testing::Not;

// The user's program: a configuration with a global, an access path, a task and an instance.
constexpr const char* kUserProgram = R"(
TYPE Mode : (Idle, Busy); END_TYPE
VAR_GLOBAL gvl_count : DINT; END_VAR
PROGRAM Counter
VAR_OUTPUT n : DINT; m : Mode; END_VAR
n := n + 1; gvl_count := n; m := Busy;
END_PROGRAM
CONFIGURATION Machine
  VAR_GLOBAL cfg_limit : DINT := 7; END_VAR
  VAR_ACCESS limit_path : cfg_limit : DINT READ_WRITE; END_VAR
  RESOURCE R ON PLC
    TASK Fast(INTERVAL := T#2ms, PRIORITY := 1);
    PROGRAM UserInst WITH Fast : Counter;
  END_RESOURCE
END_CONFIGURATION
)";

// The harness: its own configuration running the user's program.
constexpr const char* kHarness = R"(
CONFIGURATION Harness
  RESOURCE R ON PLC
    TASK Suite(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM Under WITH Suite : Counter;
  END_RESOURCE
END_CONFIGURATION
)";

TEST(IgnoredConfigurations, OnlyTheHarnessConfigurationRemains) {
    OptionsCompilation compilation;
    const FileId user = compilation.add("user.st", kUserProgram);
    compilation.add("harness.st", kHarness);
    ASSERT_TRUE(compilation.compile({.ignored_configurations = {user}})) << compilation.errors();

    ASSERT_EQ(compilation.image().tasks.size(), 1u);
    EXPECT_EQ(compilation.image().tasks[0].name, "Suite");
    const auto symbols = compilation.symbols();
    EXPECT_THAT(symbols, Contains("Under"));
    EXPECT_THAT(symbols, Contains("gvl_count")); // the global variable list stays
    for (const char* gone : {"Machine.cfg_limit", "limit_path", "UserInst"}) {
        EXPECT_THAT(symbols, Not(Contains(gone)));
    }
    ASSERT_TRUE(compilation.run(3)) << compilation.errors();
    EXPECT_EQ(compilation.get("Under.n"), 3);
    EXPECT_EQ(compilation.get("gvl_count"), 3);
    EXPECT_EQ(compilation.get("Under.m"), 1); // the user's enumeration type stays
}

TEST(IgnoredConfigurations, WithoutTheOptionBothConfigurationsAreCompiled) {
    OptionsCompilation compilation;
    compilation.add("user.st", kUserProgram);
    compilation.add("harness.st", kHarness);
    ASSERT_TRUE(compilation.compile()) << compilation.errors();
    EXPECT_THAT(compilation.symbols(), Contains("UserInst"));
    EXPECT_EQ(compilation.image().tasks.size(), 2u);
}

TEST(IgnoredConfigurations, TheirGlobalsStayAsAGlobalVariableList) {
    const std::string uses = R"(
FUNCTION_BLOCK Reader
VAR_OUTPUT v : DINT; END_VAR
v := cfg_limit + res_offset;
END_FUNCTION_BLOCK
PROGRAM External
VAR_EXTERNAL cfg_limit : DINT; END_VAR
VAR r : Reader; END_VAR
r();
END_PROGRAM
)";
    OptionsCompilation compilation;
    const FileId user = compilation.add(
        "user.st", uses + "CONFIGURATION Machine\nVAR_GLOBAL cfg_limit : DINT := 40; END_VAR\n"
                          "RESOURCE R ON PLC\nVAR_GLOBAL res_offset : DINT := 2; END_VAR\n"
                          "PROGRAM P : External;\nEND_RESOURCE\nEND_CONFIGURATION\n");
    compilation.add("harness.st", R"(
PROGRAM Probe
VAR r : Reader; END_VAR
r();
END_PROGRAM
CONFIGURATION Harness
  RESOURCE R ON PLC
    TASK Suite(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM Under WITH Suite : Probe;
  END_RESOURCE
END_CONFIGURATION
)");
    ASSERT_TRUE(compilation.compile({.ignored_configurations = {user}})) << compilation.errors();
    // Their tasks and program instances are gone; the variables are globals of the program.
    EXPECT_THAT(compilation.symbols(), Not(Contains(HasSubstr("Machine"))));
    EXPECT_THAT(compilation.symbols(), Contains("cfg_limit"));
    ASSERT_TRUE(compilation.run(1)) << compilation.errors();
    EXPECT_EQ(compilation.get("Under.r.v"), 42);
}

TEST(IgnoredConfigurations, AFileThatIsNotCompiledIsAnError) {
    OptionsCompilation compilation;
    compilation.add("user.st", kUserProgram);
    const FileId stray = compilation.sources().add("stray.st", kHarness); // loaded, not compiled
    ASSERT_FALSE(compilation.compile({.ignored_configurations = {stray}}));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("error: ignored_configurations: 'stray.st' is not among the files "
                          "compiled"));
    ASSERT_FALSE(compilation.compile({.ignored_configurations = {99}}));
    EXPECT_THAT(compilation.errors(),
                HasSubstr("error: ignored_configurations: file 99 is not among the files "
                          "compiled"));
}

TEST(IgnoredConfigurations, TheFrontEndOfTheReferenceEvaluatorHonoursThem) {
    SourceManager sources;
    const FileId user = sources.add("user.st", kUserProgram);
    const FileId harness = sources.add("harness.st", kHarness);
    const std::vector<FileId> files = {user, harness};
    Diagnostics diagnostics;
    const auto front_end =
        types::analyse(sources, files, diagnostics, {.ignored_configurations = {user}});
    ASSERT_FALSE(diagnostics.has_errors()) << render(diagnostics, sources);
    ASSERT_TRUE(front_end->program);
    EXPECT_TRUE(front_end->units[0].configurations.empty());
    EXPECT_EQ(front_end->units[1].configurations.size(), 1u);
}

} // namespace
} // namespace eposp::compiler::test
