// CompileOptions::if_conversion: turned off (as coverage compiles do), a simple IF keeps its
// conditional branch, whose outcomes coverage counts; the results are the same either way.
#include "compile_options_harness.hpp"
#include "eposp/vm/instruction.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

constexpr const char* kProgram = R"(
PROGRAM Main
VAR n : DINT; big : DINT; END_VAR
n := n + 1;
IF n > 2 THEN
    big := 1;
ELSE
    big := 0;
END_IF
END_PROGRAM
)";

std::size_t conditional_branches(const vm::Image& image) {
    std::size_t count = 0;
    for (const vm::Instruction& ins : image.code) {
        count += ins.opcode != vm::Opcode::Jmp && vm::branch_target(ins) ? 1 : 0;
    }
    return count;
}

TEST(IfConversionOption, OffASimpleIfKeepsItsBranchWithTheSameResults) {
    OptionsCompilation converted;
    converted.add("main.st", kProgram);
    ASSERT_TRUE(converted.compile()) << converted.errors();
    OptionsCompilation branching;
    branching.add("main.st", kProgram);
    ASSERT_TRUE(branching.compile({.if_conversion = false})) << branching.errors();

    EXPECT_EQ(conditional_branches(converted.image()), 0U);
    EXPECT_EQ(conditional_branches(branching.image()), 1U);
    for (OptionsCompilation* compilation : {&converted, &branching}) {
        ASSERT_TRUE(compilation->run(2)) << compilation->errors(); // each run starts afresh
        EXPECT_EQ(compilation->get("Main.big"), 0);
        ASSERT_TRUE(compilation->run(3)) << compilation->errors();
        EXPECT_EQ(compilation->get("Main.big"), 1);
    }
}

} // namespace
} // namespace eposp::compiler::test
