// `eposp check` as a user meets it: exit 0 for a program whose names all resolve, 1 and a
// compiler-style diagnostic with a caret otherwise (or JSON lines); `eposp explain` says what a
// diagnostic's code means.
#include "eposp_command.hpp"

#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <string>
#include <utility>
#include <vector>

namespace eposp::device {
namespace {

using testing::HasSubstr;
using testing::Not;

constexpr const char* kConfiguration = "CONFIGURATION Config0\n"
                                       "  VAR_GLOBAL total : DINT; END_VAR\n"
                                       "  RESOURCE Res0 ON PLC\n"
                                       "    TASK Cyclic(INTERVAL := T#1ms, PRIORITY := 0);\n"
                                       "    PROGRAM Inst0 WITH Cyclic : Main;\n"
                                       "  END_RESOURCE\n"
                                       "END_CONFIGURATION\n";

TEST(CheckCommand, CorrectProgramInTwoFilesExitsWithZero) {
    const std::string main = write_source("main.st", "PROGRAM Main\n"
                                                     "  VAR_EXTERNAL total : DINT; END_VAR\n"
                                                     "  total := total + 1;\n"
                                                     "END_PROGRAM\n");
    const std::string config = write_source("config.st", kConfiguration);
    const auto result = eposp("check " + main + " " + config);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output, "");
}

TEST(CheckCommand, UndeclaredIdentifierExitsWithOneAndShowsTheCaret) {
    const std::string main = write_source("main.st", "PROGRAM Main\n"
                                                     "  VAR_EXTERNAL total : DINT; END_VAR\n"
                                                     "  total := totl + 1;\n"
                                                     "END_PROGRAM\n");
    const std::string config = write_source("config.st", kConfiguration);
    const auto result = eposp("check " + main + " " + config);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output,
                HasSubstr(main + ":3:12: error: undeclared identifier 'totl' [E0201]\n"
                                 "  total := totl + 1;\n"
                                 "           ^~~~\n"));
}

TEST(CheckCommand, SyntaxErrorExitsWithOne) {
    const std::string main = write_source("main.st", "PROGRAM Main\n  x := ;\nEND_PROGRAM\n");
    const auto result = eposp("check " + main);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(main + ":2:"));
}

TEST(CheckCommand, SyntaxErrorInOneFileIsTheOnlyErrorReported) {
    const std::string main = write_source("main.st", "PROGRAM Main\n"
                                                     "  VAR_EXTERNAL total : DINT; END_VAR\n"
                                                     "  total := ;\n"
                                                     "END_PROGRAM\n");
    const std::string config = write_source("config.st", kConfiguration);
    const auto result = eposp("check " + main + " " + config);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(main + ":3:"));
    // Main is declared, in the file that did not parse: no "unknown program type 'Main'".
    EXPECT_THAT(result.output, Not(HasSubstr(config)));
}

TEST(CheckCommand, MissingFileIsAUserError) {
    const auto result = eposp("check /nonexistent/main.st");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp check: error:"));
    EXPECT_THAT(result.output, HasSubstr("/nonexistent/main.st"));
}

TEST(CheckCommand, HelpDescribesTheCommand) {
    const auto result = eposp("check --help");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("files"));
}

TEST(CheckCommand, AProgramImageIsSaidToBeNoSource) {
    const std::string source = write_source("main.st", "PROGRAM Main\nEND_PROGRAM\n");
    const std::string image = scratch("main.epx").string();
    ASSERT_EQ(eposp("build " + source + " -o " + image).exit_code, 0);
    // Under another name too: the magic, not the name, says it is an image.
    const auto renamed = scratch("renamed.st");
    std::filesystem::copy_file(image, renamed, std::filesystem::copy_options::overwrite_existing);
    for (const std::string& path : {image, renamed.string()}) {
        const auto result = eposp("check " + path);
        EXPECT_EQ(result.exit_code, 1) << result.output;
        EXPECT_THAT(result.output,
                    HasSubstr(path + " is a program image, not Structured Text source"));
    }
}

// An escape sequence in a source must not reach the terminal raw (it could clear the screen or
// hide the rest of the diagnostic); it is shown as \x1b.
TEST(CheckCommand, ControlCharactersOfTheSourceAreEscaped) {
    const std::string main = write_source(
        "main.st", "PROGRAM Main\n  VAR x : INT; END_VAR\n  x := \x1b[2J\r1;\nEND_PROGRAM\n");
    const auto result = eposp("check " + main);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("\\x1b[2J\\x0d1;"));
    EXPECT_THAT(result.output, Not(HasSubstr("\x1b")));
    EXPECT_THAT(result.output, Not(HasSubstr("\r")));
}

TEST(CheckCommand, ErrorFormatJsonPrintsOneObjectPerDiagnostic) {
    const std::string main = write_source("main.st", "PROGRAM Main\n"
                                                     "  VAR x : INT; END_VAR\n"
                                                     "  x := totl + 1;\n"
                                                     "END_PROGRAM\n");
    const auto result = eposp("check --error-format json " + main);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output,
                HasSubstr("{\"code\":\"E0201\",\"severity\":\"error\",\"title\":\"undeclared "
                          "identifier\",\"message\":\"undeclared identifier 'totl'\",\"file\":\"" +
                          main +
                          "\",\"range\":{\"start\":{\"line\":3,\"column\":8},\"end\":{\"line\":3,"
                          "\"column\":11}},\"notes\":[],\"fix_it\":null}\n"));
    EXPECT_THAT(result.output, Not(HasSubstr("^~~~")));
}

TEST(CheckCommand, BuildAndRunTakeTheErrorFormatToo) {
    const std::string main =
        write_source("main.st", "PROGRAM Main\nVAR x : INT; END_VAR\nx = 1;\nEND_PROGRAM\n");
    for (const std::string& command :
         std::vector<std::string>{"build -o " + scratch("main.epx").string(), "run --for 1s"}) {
        const auto result = eposp(command + " --error-format json " + main);
        EXPECT_EQ(result.exit_code, 1) << command;
        EXPECT_THAT(result.output, HasSubstr("{\"code\":\"E0107\",")) << command;
        // The fix-it: ' := ' in place of ' = '.
        EXPECT_THAT(result.output, HasSubstr("\"fix_it\":{\"replacement\":\" := \",")) << command;
    }
}

TEST(CheckCommand, StopsBeforeCodeGenerationSoALimitOnlyItMeetsPassesCheckButNotBuild) {
    // Static data beyond what an image holds (E0502: two global arrays of 40 MB, each under
    // the limit) is found when code generation lays the globals out
    // (codegen/program_limits.cpp): `eposp check` runs parse, names, types and checks only
    // (compiler::check).
    const std::string main =
        write_source("main.st", "VAR_GLOBAL a, b : ARRAY[1..5000000] OF LREAL; END_VAR\n"
                                "PROGRAM Main\n"
                                "a[1] := b[2];\n"
                                "END_PROGRAM\n");
    const auto checked = eposp("check " + main);
    EXPECT_EQ(checked.exit_code, 0) << checked.output;
    EXPECT_EQ(checked.output, "");
    const auto built = eposp("build " + main + " -o " + scratch("main.epx").string());
    EXPECT_EQ(built.exit_code, 1);
    EXPECT_THAT(built.output, HasSubstr("[E0502]"));
}

TEST(CheckCommand, AnErrorOfEveryStageBeforeCodeGenerationFailsCheck) {
    const std::vector<std::pair<std::string, std::string>> programs = {
        {"E0107", "PROGRAM Main\nVAR x : INT; END_VAR\nx = 1;\nEND_PROGRAM\n"},         // syntax
        {"E0201", "PROGRAM Main\nVAR x : INT; END_VAR\nx := y;\nEND_PROGRAM\n"},        // names
        {"E0303", "PROGRAM Main\nVAR x : INT; END_VAR\nx := x + TRUE;\nEND_PROGRAM\n"}, // types
        {"E0401", "PROGRAM Main\nVAR CONSTANT x : INT := 1; END_VAR\nx := 2;\nEND_PROGRAM\n"},
    };
    for (const auto& [code, program] : programs) {
        const std::string main = write_source("main.st", program);
        const auto result = eposp("check " + main);
        EXPECT_EQ(result.exit_code, 1) << code;
        EXPECT_THAT(result.output, HasSubstr("[" + code + "]")) << result.output;
        EXPECT_THAT(result.output, HasSubstr("eposp check: error: " + main + " has errors"));
    }
}

TEST(CheckCommand, ErrorFormatIsHumanOrJson) {
    const std::string main = write_source("main.st", "PROGRAM Main\nEND_PROGRAM\n");
    const auto result = eposp("check --error-format xml " + main);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("--error-format"));
}

TEST(ExplainCommand, ExplainsACodeWithTheWrongAndTheRightExample) {
    const auto result = eposp("explain e0201");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("E0201 (error, names): undeclared identifier\n"));
    EXPECT_THAT(result.output, HasSubstr("This produces it:\n\n    PROGRAM Main\n"));
    EXPECT_THAT(result.output, HasSubstr("    totl := 1;\n"));
    EXPECT_THAT(result.output, HasSubstr("Fixed:\n\n    PROGRAM Main\n"));
    EXPECT_THAT(result.output, HasSubstr("    total := 1;\n"));
}

TEST(ExplainCommand, WithoutACodeListsEveryCode) {
    const auto result = eposp("explain");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("E0101  syntax   syntax error\n"));
    EXPECT_THAT(result.output, HasSubstr("W0401  checks   unused variable\n"));
}

TEST(ExplainCommand, AnUnknownCodeIsAUserError) {
    const auto result = eposp("explain E9999");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output,
                HasSubstr("eposp explain: error: no diagnostic has the code 'E9999'"));
}

} // namespace
} // namespace eposp::device
