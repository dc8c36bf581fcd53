// Code generation runs only on a program the checking stage passed. Where it meets what the
// checks refuse, the checks missed it: an internal compiler error (E0001) and no image, never a
// crash or code for it. Code generation is run here without the checks to make such a gap.
#include "codegen/program_generator.hpp"
#include "eposp/compiler/types/front_end.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace eposp::compiler {
namespace {

TEST(ChecksGap, IsAnInternalErrorThatNamesTheRule) {
    SourceManager sources;
    const std::vector<FileId> files{sources.add("main.st", R"st(
PROGRAM Main
VAR CONSTANT limit : INT := 3; END_VAR
limit := 4;
END_PROGRAM
)st")};
    Diagnostics diagnostics;
    const auto front_end = types::analyse(sources, files, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors()) << render(diagnostics, sources);
    codegen::ProgramGenerator generator({*front_end->model, front_end->units, 0},
                                        {*front_end->library_model, front_end->library_units},
                                        *front_end->program, diagnostics, {});
    EXPECT_FALSE(generator.generate().has_value());
    ASSERT_EQ(diagnostics.all().size(), 1u) << render(diagnostics, sources);
    EXPECT_EQ(diagnostics.all().front().code, DiagnosticCode::E0001);
    EXPECT_NE(diagnostics.all().front().message.find("(E0401)"), std::string::npos)
        << diagnostics.all().front().message;
}

} // namespace
} // namespace eposp::compiler
