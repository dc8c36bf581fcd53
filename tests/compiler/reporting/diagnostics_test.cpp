// Diagnostics are data, rendered in one place as `file:line:col: severity: message`, the source
// line and a caret; a run reports many errors.
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/source_manager.hpp"
#include "parse_helpers.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler {
namespace {

using test::parse_text;

TEST(DiagnosticRendering, ShowsLocationSourceLineAndCaret) {
    const test::Parsed parsed =
        parse_text("PROGRAM Main\n  x := 1\n  y := 2;\nEND_PROGRAM\n", "main.st");
    EXPECT_EQ(parsed.rendered(), "main.st:2:9: error: expected ';' after statement [E0101]\n"
                                 "  x := 1\n"
                                 "        ^\n");
}

TEST(DiagnosticRendering, UnderlinesTheWholeRangeOnItsLine) {
    SourceManager sources;
    const FileId file = sources.add("a.st", "x := INT#70000;\n");
    Diagnostics diagnostics;
    diagnostics.error(DiagnosticCode::E0104, {file, {1, 6}, {1, 14}}, "out of range");
    EXPECT_EQ(render(diagnostics, sources), "a.st:1:6: error: out of range [E0104]\n"
                                            "x := INT#70000;\n"
                                            "     ^~~~~~~~~\n");
}

TEST(DiagnosticRendering, CaretCountsCharactersNotBytesAndKeepsTabs) {
    SourceManager sources;
    const FileId file = sources.add("u.st", "\ts := 'äöü' + ;\n");
    Diagnostics diagnostics;
    diagnostics.error(DiagnosticCode::E0101, {file, {1, 15}, {1, 15}}, "expected an expression");
    EXPECT_EQ(render(diagnostics, sources), "u.st:1:15: error: expected an expression [E0101]\n"
                                            "\ts := 'äöü' + ;\n"
                                            "\t             ^\n");
}

TEST(DiagnosticRendering, NotesAndWarningsFollowTheSameFormat) {
    SourceManager sources;
    const FileId file = sources.add("n.st", "a\nb\n");
    Diagnostics diagnostics;
    Diagnostic unused(DiagnosticCode::W0401, {file, {2, 1}, {2, 1}}, "unused");
    unused.notes.push_back({{file, {1, 1}, {1, 1}}, "declared here"});
    diagnostics.report(std::move(unused));
    EXPECT_EQ(render(diagnostics, sources), "n.st:2:1: warning: unused [W0401]\nb\n^\n"
                                            "n.st:1:1: note: declared here\na\n^\n");
    EXPECT_FALSE(diagnostics.has_errors());
}

TEST(DiagnosticRendering, CrLfLineEndingsAreNotQuoted) {
    const test::Parsed parsed = parse_text("PROGRAM P\r\nx := ;\r\nEND_PROGRAM\r\n");
    EXPECT_EQ(parsed.rendered(), "test.st:2:6: error: expected an expression, found ';' [E0101]\n"
                                 "x := ;\n"
                                 "     ^\n");
}

TEST(Diagnostics, StopCollectingErrorsAfterTheLimit) {
    SourceManager sources;
    const FileId file = sources.add("l.st", "");
    Diagnostics diagnostics(2);
    for (int i = 0; i < 5; ++i) {
        diagnostics.error(DiagnosticCode::E0201, {file, {1, 1}, {1, 1}}, "problem");
    }
    ASSERT_EQ(diagnostics.all().size(), 3u);
    EXPECT_EQ(diagnostics.all()[2].message, "too many errors; stopping after 2");
    EXPECT_EQ(diagnostics.all()[2].code, DiagnosticCode::E0004);
}

TEST(ErrorRecovery, ReportsEveryBrokenStatement) {
    const test::Parsed parsed = parse_text("PROGRAM P\n"
                                           "  a := 1\n"
                                           "  b := 2;\n"
                                           "  c := (3 + ;\n"
                                           "  IF d THEN e := 4 END_IF;\n"
                                           "  f := 5;\n"
                                           "END_PROGRAM\n");
    std::vector<std::pair<std::uint32_t, std::string>> errors;
    for (const Diagnostic& diagnostic : parsed.diagnostics.all()) {
        errors.emplace_back(diagnostic.range.begin.line, diagnostic.message);
    }
    EXPECT_THAT(errors, testing::ElementsAre(testing::Pair(2, "expected ';' after statement"),
                                             testing::Pair(4, "expected an expression, found ';'"),
                                             testing::Pair(5, "expected ';' after statement")));
}

TEST(ErrorRecovery, ContinuesIntoTheNextPou) {
    const test::Parsed parsed = parse_text("FUNCTION_BLOCK A\n  VAR x : INT END_VAR\n"
                                           "END_FUNCTION_BLOCK\n"
                                           "PROGRAM B\n  y := ;\nEND_PROGRAM\n");
    ASSERT_EQ(parsed.diagnostics.all().size(), 2u) << parsed.rendered();
    EXPECT_EQ(parsed.diagnostics.all()[0].message, "expected ':=' or ';', found 'END_VAR'");
    EXPECT_EQ(parsed.diagnostics.all()[1].range.begin.line, 5u);
}

TEST(ErrorMessages, SpeakTheLanguageOfTheProgrammer) {
    EXPECT_EQ(parse_text("PROGRAM P x := 1; END_FUNCTION").first_message(),
              "expected 'END_PROGRAM', found 'END_FUNCTION'");
    EXPECT_EQ(parse_text("PROGRAM P x := 1 € 2; END_PROGRAM").first_message(),
              "unexpected character '€'");
    EXPECT_EQ(parse_text("TYPE T : STRUCT x : INT END_STRUCT END_TYPE").first_message(),
              "expected ':=' or ';', found 'END_STRUCT'");
    EXPECT_EQ(parse_text("PROGRAM P VAR x INT; END_VAR END_PROGRAM").first_message(),
              "expected 'AT', ':' or ',', found 'INT'");
}

TEST(ErrorMessages, MissingKeywordIsReportedRightAfterThePreviousToken) {
    const test::Parsed missing_then = parse_text("PROGRAM P\nIF x\n  y := 1; END_IF; END_PROGRAM");
    EXPECT_EQ(missing_then.first_message(), "expected 'THEN'");
    EXPECT_EQ(missing_then.diagnostics.all().front().range.begin, (SourcePosition{2, 5}));
    const test::Parsed missing_end = parse_text("PROGRAM P\nx := 1;");
    EXPECT_EQ(missing_end.first_message(), "expected 'END_PROGRAM'");
    EXPECT_EQ(missing_end.diagnostics.all().front().range.begin, (SourcePosition{2, 8}));
}

TEST(SourceManager, LoadingAMissingFileSaysWhy) {
    SourceManager sources;
    const auto file = sources.load("/nonexistent/dir/main.st");
    ASSERT_FALSE(file);
    EXPECT_THAT(file.error(), testing::HasSubstr("cannot open '/nonexistent/dir/main.st'"));
}

TEST(SourceManager, QuotesAnyLineOfAnyFile) {
    SourceManager sources;
    sources.add("one.st", "first\nsecond");
    const FileId two = sources.add("two.st", "alpha\r\nbeta\r\n");
    EXPECT_EQ(sources.line(two, 2), "beta");
    EXPECT_EQ(sources.line(0, 2), "second");
    EXPECT_EQ(sources.line(0, 9), "");
    EXPECT_EQ(sources.path(two), "two.st");
}

} // namespace
} // namespace eposp::compiler
