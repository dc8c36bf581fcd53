// `--error-format json`: each diagnostic one JSON object per line, with its code, severity,
// location, notes and fix-it (docs/diagnostics.md, "JSON").
#include "eposp/compiler/diagnostics_json.hpp"
#include "eposp/compiler/source_manager.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace eposp::compiler {
namespace {

using nlohmann::json;

TEST(DiagnosticsJson, OneObjectPerLineWithCodeLocationNotesAndFixIt) {
    SourceManager sources;
    const FileId file = sources.add("main.st", "x = 1;\ny := 2;\n");
    Diagnostics diagnostics;
    Diagnostic statement(DiagnosticCode::E0107, {file, {1, 1}, {1, 5}}, "does nothing");
    statement.notes.push_back({{file, {2, 1}, {2, 1}}, "like this"});
    statement.fix_it = FixIt{{file, {1, 3}, {1, 3}}, ":="};
    diagnostics.report(std::move(statement));
    diagnostics.warning(DiagnosticCode::W0407, {}, "no program");

    const std::string text = render_json(diagnostics, sources);
    const std::size_t newline = text.find('\n');
    ASSERT_NE(newline, std::string::npos);
    ASSERT_EQ(text.back(), '\n');
    const json first = json::parse(text.substr(0, newline));
    const json second = json::parse(text.substr(newline + 1));
    EXPECT_EQ(first["code"], "E0107");
    EXPECT_EQ(first["severity"], "error");
    EXPECT_EQ(first["title"], "statement without effect");
    EXPECT_EQ(first["message"], "does nothing");
    EXPECT_EQ(first["file"], "main.st");
    EXPECT_EQ(first["range"], json::parse(R"({"start":{"line":1,"column":1},
                                               "end":{"line":1,"column":5}})"));
    ASSERT_EQ(first["notes"].size(), 1U);
    EXPECT_EQ(first["notes"][0]["message"], "like this");
    EXPECT_EQ(first["notes"][0]["range"]["start"]["line"], 2);
    EXPECT_EQ(first["fix_it"]["replacement"], ":=");
    EXPECT_EQ(first["fix_it"]["range"]["start"]["column"], 3);
    EXPECT_EQ(second["code"], "W0407");
    EXPECT_EQ(second["severity"], "warning");
    EXPECT_EQ(second["file"], "main.st"); // about the program as a whole, without a line
    EXPECT_TRUE(second["range"].is_null());
    EXPECT_TRUE(second["fix_it"].is_null());
}

TEST(DiagnosticsJson, TextThatIsNotUtf8IsReplacedNotThrownOn) {
    SourceManager sources;
    Diagnostics diagnostics;
    diagnostics.error(DiagnosticCode::E0201, {}, "undeclared identifier 'gr\xfc\xdf'");
    const json parsed = json::parse(render_json(diagnostics, sources));
    EXPECT_EQ(parsed["code"], "E0201");
    EXPECT_TRUE(parsed["file"].is_null()); // no file at all: a compile option's
    EXPECT_TRUE(parsed["range"].is_null());
}

TEST(DiagnosticRendering, AFixItIsShownUnderTheCaret) {
    SourceManager sources;
    const FileId file = sources.add("main.st", "x = 1;\n");
    Diagnostics diagnostics;
    Diagnostic statement(DiagnosticCode::E0107, {file, {1, 3}, {1, 3}}, "does nothing");
    statement.fix_it = FixIt{{file, {1, 3}, {1, 3}}, ":="};
    diagnostics.report(std::move(statement));
    EXPECT_EQ(render(diagnostics, sources), "main.st:1:3: error: does nothing [E0107]\n"
                                            "x = 1;\n"
                                            "  ^\n"
                                            "  :=\n");
}

} // namespace
} // namespace eposp::compiler
