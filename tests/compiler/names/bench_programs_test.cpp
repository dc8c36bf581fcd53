// The seven benchmark programs of ../shared/bench (copied to inputs/) are real-shaped ST: every
// one must parse into an AST and resolve every name without a single diagnostic.
#include "eposp/compiler/parser.hpp"
#include "eposp/compiler/sema/resolver.hpp"

#include <gtest/gtest.h>
#include <string>

namespace eposp::compiler {
namespace {

class BenchProgram : public testing::TestWithParam<std::string> {
protected:
    void SetUp() override {
        const auto file = sources_.load(std::string(EPOSP_SOURCE_DIR) + "/tests/compiler/inputs/" +
                                        GetParam() + ".st");
        ASSERT_TRUE(file) << file.error();
        unit_ = parse(sources_, *file, diagnostics_);
    }

    SourceManager sources_;
    Diagnostics diagnostics_;
    ast::CompilationUnit unit_;
};

TEST_P(BenchProgram, ParsesWithoutDiagnostics) {
    EXPECT_TRUE(diagnostics_.all().empty()) << render(diagnostics_, sources_);
    EXPECT_FALSE(unit_.pous.empty());
    ASSERT_EQ(unit_.configurations.size(), 1u);
    const ast::Resource& resource = unit_.configurations.front().resources.front();
    ASSERT_EQ(resource.programs.size(), 1u);
    EXPECT_EQ(resource.programs.front().type.name, "Main");
    ASSERT_EQ(resource.tasks.size(), 1u);
    EXPECT_TRUE(resource.tasks.front().interval);
}

TEST_P(BenchProgram, ResolvesWithoutDiagnostics) {
    const sema::SemanticModel model = sema::resolve({&unit_, 1}, diagnostics_);
    EXPECT_TRUE(diagnostics_.all().empty()) << render(diagnostics_, sources_);
    const ast::ProgramInstance& instance =
        unit_.configurations.front().resources.front().programs.front();
    const sema::Symbol* program = model.resolved(instance.type);
    ASSERT_NE(program, nullptr);
    EXPECT_EQ(program->kind, sema::SymbolKind::Pou);
}

INSTANTIATE_TEST_SUITE_P(Shared, BenchProgram,
                         testing::Values("bubble_sort", "conveyor_fsm", "crc32", "fb_channels",
                                         "pid_plant", "sieve", "strings"),
                         [](const auto& program) { return program.param; });

} // namespace
} // namespace eposp::compiler
