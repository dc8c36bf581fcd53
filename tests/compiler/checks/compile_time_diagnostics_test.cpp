// Mistakes the compiler can see and the user expects to hear about: a constant divisor of zero
// (an error, as a constant index out of range is), a string literal cut to fit its target, and
// a file that is not UTF-8 (read as Windows-1252, as CODESYS exports it).
#include "codegen_harness.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

using testing::HasSubstr;
using testing::Not;

TEST(CompileTimeDiagnostics, ConstantDivisionByZeroIsAnError) {
    const std::string declarations = "PROGRAM Main\nVAR x, y : DINT := 7; r : REAL; END_VAR\n"
                                     "VAR CONSTANT zero : DINT := 0; END_VAR\n";
    EXPECT_THAT(diagnostics_of(declarations + "x := 1 / 0;\nEND_PROGRAM\n"),
                HasSubstr("test.st:4:10: error: division by zero"));
    EXPECT_THAT(diagnostics_of(declarations + "x := y MOD 0;\nEND_PROGRAM\n"),
                HasSubstr("test.st:4:12: error: MOD by zero"));
    EXPECT_THAT(diagnostics_of(declarations + "x := y / (zero * 2);\nEND_PROGRAM\n"),
                HasSubstr("test.st:4:11: error: division by zero"));
    EXPECT_THAT(diagnostics_of(declarations + "x := DIV(y, 3 - 3);\nEND_PROGRAM\n"),
                HasSubstr("test.st:4:13: error: division by zero"));
    EXPECT_THAT(diagnostics_of(declarations + "r := r / 0.0;\nEND_PROGRAM\n"),
                HasSubstr("test.st:4:10: error: division by zero"));
    EXPECT_EQ(diagnostics_of(declarations + "x := y / (zero + 2) + y MOD 5;\nEND_PROGRAM\n"), "");
}

TEST(CompileTimeDiagnostics, StringLiteralLongerThanItsTargetIsCutWithAWarning) {
    StProgram run(R"(
FUNCTION Length : INT
VAR_INPUT p : STRING[4]; END_VAR
Length := LEN(p);
END_FUNCTION
PROGRAM Main
VAR s : STRING[3] := 'abcdef'; t : STRING[3]; n : INT; fits : STRING[3] := 'xyz'; END_VAR
t := 'ghijk';
n := Length('lmnopq');
fits := SEL(t = 'ghijk', 'yes', 'no'); (* a comparison cuts nothing *)
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.s"), "abc");
    EXPECT_EQ(run.get_string("Main.t"), "ghi");
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 4);
    EXPECT_THAT(run.errors(), HasSubstr("test.st:7:22: warning: this string of 6 characters is "
                                        "cut to the 3 of STRING[3]"));
    EXPECT_THAT(run.errors(), HasSubstr("test.st:8:6: warning: this string of 5 characters is "
                                        "cut to the 3 of STRING[3]"));
    EXPECT_THAT(run.errors(), HasSubstr("test.st:9:13: warning: this string of 6 characters is "
                                        "cut to the 4 of STRING[4]"));
    EXPECT_THAT(run.errors(), Not(HasSubstr(":7:76:"))); // 'xyz' fits
    EXPECT_THAT(run.errors(), Not(HasSubstr(":10:")));
    EXPECT_EQ(run.get_string("Main.fits"), "yes"); // t holds 'ghi': G is FALSE, SEL gives IN0
}

TEST(CompileTimeDiagnostics, AFileThatIsNotUtf8IsReadAsWindows1252WithOneWarning) {
    // A CODESYS export: a degree sign in a comment, German letters in a string, a euro sign.
    StProgram run("PROGRAM Main\n"
                  "VAR s : STRING; e : STRING; END_VAR (* Temperatur in \xB0"
                  "C *)\n"
                  "s := 'Gr\xFC\xDF"
                  "e';\n"
                  "e := '\x80';\n"
                  "END_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get_string("Main.s"), "Gr\xC3\xBC\xC3\x9F"
                                        "e");
    EXPECT_EQ(run.get_string("Main.e"), "\xE2\x82\xAC");
    EXPECT_THAT(run.errors(), HasSubstr("test.st:2:54: warning: the file is not valid UTF-8 text "
                                        "here; it is read as Windows-1252"));
    EXPECT_EQ(run.errors().find("warning"), run.errors().rfind("warning")) << run.errors();
}

} // namespace
} // namespace eposp::compiler::test
