// Every ST example of docs/function-blocks.md compiles against the motion library: what a user
// copies from the manual is a program `eposp` accepts. A fragment's variables are declared in
// the HTML comment before it (`<!-- declared: ... -->`, invisible when the page is rendered); a
// fragment that is a whole PROGRAM stands alone.

#include "motion_harness.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace eposp::plcopen::test {
namespace {

struct Example {
    std::string declarations;
    std::string code;
    std::size_t line = 0; ///< of its opening fence
};

std::vector<Example> examples_of(const std::string& path) {
    std::ifstream in(path);
    std::vector<Example> examples;
    std::string declarations;
    std::optional<Example> open;
    std::string text;
    constexpr std::string_view kDeclared = "<!-- declared: ";
    for (std::size_t number = 1; std::getline(in, text); ++number) {
        if (open) {
            if (text == "```") {
                examples.push_back(std::move(*open));
                open.reset();
            } else {
                open->code += text + "\n";
            }
        } else if (text.starts_with(kDeclared)) {
            declarations = text.substr(kDeclared.size(), text.rfind(" -->") - kDeclared.size());
        } else if (text == "```iecst") {
            open = Example{
                .declarations = std::exchange(declarations, {}), .code = {}, .line = number};
        }
    }
    return examples;
}

std::string program_of(const Example& example) {
    if (example.code.starts_with("PROGRAM")) {
        return example.code;
    }
    return "PROGRAM Main\nVAR\n" + example.declarations + "\nEND_VAR\n" + example.code +
           "END_PROGRAM\n";
}

TEST(FunctionBlocksManual, EveryExampleCompilesWithTheMotionLibrary) {
    const auto examples = examples_of(std::string(EPOSP_SOURCE_DIR) + "/docs/function-blocks.md");
    ASSERT_GE(examples.size(), 20U);
    for (const Example& example : examples) {
        SCOPED_TRACE("docs/function-blocks.md:" + std::to_string(example.line));
        std::string diagnostics;
        EXPECT_TRUE(MotionHarness::compile(program_of(example), &diagnostics)) << diagnostics;
    }
}

} // namespace
} // namespace eposp::plcopen::test
