// The seven benchmark programs of ../shared/bench (copied to inputs/) are real-shaped ST: every
// one must parse into an AST without a single diagnostic.
#include "eposp/compiler/parser.hpp"

#include <gtest/gtest.h>
#include <string>

namespace eposp::compiler {
namespace {

class BenchProgram : public testing::TestWithParam<std::string> {};

TEST_P(BenchProgram, ParsesWithoutDiagnostics) {
    SourceManager sources;
    const auto file = sources.load(std::string(EPOSP_SOURCE_DIR) + "/tests/compiler/inputs/" +
                                   GetParam() + ".st");
    ASSERT_TRUE(file) << file.error();
    Diagnostics diagnostics;
    const ast::CompilationUnit unit = parse(sources, *file, diagnostics);
    EXPECT_TRUE(diagnostics.all().empty()) << render(diagnostics, sources);
    EXPECT_FALSE(unit.pous.empty());
    ASSERT_EQ(unit.configurations.size(), 1u);
    const ast::Resource& resource = unit.configurations.front().resources.front();
    ASSERT_EQ(resource.programs.size(), 1u);
    EXPECT_EQ(resource.programs.front().type.name, "Main");
    ASSERT_EQ(resource.tasks.size(), 1u);
    EXPECT_TRUE(resource.tasks.front().interval);
}

INSTANTIATE_TEST_SUITE_P(Shared, BenchProgram,
                         testing::Values("bubble_sort", "conveyor_fsm", "crc32", "fb_channels",
                                         "pid_plant", "sieve", "strings"),
                         [](const auto& program) { return program.param; });

} // namespace
} // namespace eposp::compiler
