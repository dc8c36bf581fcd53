// The catalogue is what `eposp explain` prints, so it is held to its word: every code's wrong
// example yields that code, and its right example compiles without any diagnostic.
#include "diagnostic_example.hpp"
#include "eposp/compiler/diagnostic_code.hpp"
#include "eposp/compiler/source_manager.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <iterator>
#include <ostream>
#include <set>
#include <vector>

namespace eposp::compiler {

// Test names and failure messages show the code, not the entry's bytes.
void PrintTo(const DiagnosticInfo& info, std::ostream* out) {
    *out << info.name;
}

namespace {

using test::compile_example;

std::string code_name(const testing::TestParamInfo<DiagnosticInfo>& entry) {
    return std::string(entry.param.name);
}

/// The entries with examples (CodesWithoutExamples lists the others).
std::vector<DiagnosticInfo> entries_with_examples() {
    std::vector<DiagnosticInfo> entries;
    std::copy_if(diagnostic_catalogue().begin(), diagnostic_catalogue().end(),
                 std::back_inserter(entries),
                 [](const DiagnosticInfo& info) { return !info.wrong.empty(); });
    return entries;
}

class CatalogueEntry : public testing::TestWithParam<DiagnosticInfo> {};
class CatalogueExample : public testing::TestWithParam<DiagnosticInfo> {};

TEST_P(CatalogueExample, WrongExampleYieldsItsCode) {
    const DiagnosticInfo& info = GetParam();
    const auto compiled = compile_example(info.wrong);
    EXPECT_NE(std::find(compiled.codes.begin(), compiled.codes.end(), info.code),
              compiled.codes.end())
        << info.name << "'s wrong example gives instead:\n"
        << compiled.rendered;
}

TEST_P(CatalogueExample, RightExampleCompilesClean) {
    const DiagnosticInfo& info = GetParam();
    EXPECT_EQ(compile_example(info.right).rendered, "") << info.name << "'s right example";
}

TEST_P(CatalogueEntry, HasATitleAndAnExplanation) {
    const DiagnosticInfo& info = GetParam();
    EXPECT_FALSE(info.title.empty());
    EXPECT_FALSE(info.explanation.empty());
    EXPECT_EQ(info.wrong.empty(), info.right.empty()) << info.name;
    EXPECT_EQ(find_diagnostic_code(info.name), info.code);
}

INSTANTIATE_TEST_SUITE_P(DiagnosticCatalogue, CatalogueEntry,
                         testing::ValuesIn(diagnostic_catalogue().begin(),
                                           diagnostic_catalogue().end()),
                         code_name);
INSTANTIATE_TEST_SUITE_P(DiagnosticCatalogue, CatalogueExample,
                         testing::ValuesIn(entries_with_examples()), code_name);

// Only what ST alone cannot produce goes without examples: the compiler's own defect, compile
// options, the error limit, a file's encoding, and limits that take pages of source to reach.
TEST(DiagnosticCatalogue, CodesWithoutExamplesAreOnlyThoseSTCannotShowBriefly) {
    std::set<std::string_view> without;
    for (const DiagnosticInfo& info : diagnostic_catalogue()) {
        if (info.wrong.empty()) {
            without.insert(info.name);
        }
    }
    EXPECT_EQ(without, (std::set<std::string_view>{"E0001", "E0002", "E0003", "E0004", "W0104",
                                                   "E0501", "E0503", "E0504"}));
}

TEST(DiagnosticCatalogue, AComparisonWrittenForAnAssignmentOffersColonEquals) {
    const auto compiled = compile_example("PROGRAM Main\nVAR x : INT; END_VAR\nx = 1;\n"
                                          "x=2;\nEND_PROGRAM\n");
    EXPECT_EQ(compiled.rendered,
              "example.st:3:1: error: this statement does nothing; did you mean ':=' instead of "
              "'='? [E0107]\n"
              "x = 1;\n"
              "^~~~~\n"
              "  := \n"
              "example.st:4:1: error: this statement does nothing; did you mean ':=' instead of "
              "'='? [E0107]\n"
              "x=2;\n"
              "^~~\n"
              " :=\n");
}

// A code that no call site reports is a rule the compiler does not check: the catalogue would
// promise what it does not do. (Codes without examples are held to it here only.)
TEST(DiagnosticCatalogue, EveryCodeIsReportedSomewhereInTheCompiler) {
    std::string sources;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(
             std::filesystem::path(EPOSP_SOURCE_DIR) / "compiler" / "src")) {
        if (entry.path().extension() == ".cpp" || entry.path().extension() == ".hpp") {
            std::ifstream in(entry.path());
            sources.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
    }
    for (const DiagnosticInfo& info : diagnostic_catalogue()) {
        EXPECT_NE(sources.find("DiagnosticCode::" + std::string(info.name)), std::string::npos)
            << info.name << " is in the catalogue but no call site reports it";
    }
}

TEST(DiagnosticCatalogue, CodesAreFoundInAnyCaseAndUnknownOnesAreNot) {
    EXPECT_EQ(find_diagnostic_code("e0201"), DiagnosticCode::E0201);
    EXPECT_EQ(find_diagnostic_code("E9999"), std::nullopt);
    EXPECT_EQ(find_diagnostic_code("E02011"), std::nullopt);
    EXPECT_EQ(find_diagnostic_code(""), std::nullopt);
}

TEST(DiagnosticCatalogue, SeverityComesFromTheCode) {
    SourceManager sources;
    Diagnostics diagnostics;
    diagnostics.warning(DiagnosticCode::W0401, {}, "unused");
    EXPECT_FALSE(diagnostics.has_errors());
    EXPECT_THROW(diagnostics.error(DiagnosticCode::W0401, {}, "x"), std::logic_error);
    EXPECT_THROW(diagnostics.warning(DiagnosticCode::E0201, {}, "x"), std::logic_error);
    EXPECT_EQ(render(diagnostics, sources), "warning: unused [W0401]\n");
}

} // namespace
} // namespace eposp::compiler
