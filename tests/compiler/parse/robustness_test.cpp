// Any byte string parses without crashing or hanging: garbage, truncated programs, invalid
// UTF-8 and inputs nested deeper than the stack would allow.
#include "parse_helpers.hpp"

#include <cstdint>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <random>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace eposp::compiler {
namespace {

using test::parse_text;

int fuzz_one(const std::string& input) {
    return LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()),
                                  input.size());
}

TEST(Robustness, HandPickedGarbageIsRejectedOrAcceptedCleanly) {
    const std::string inputs[] = {
        "",
        std::string("\0\0\0", 3),
        "(*",
        "/*",
        "'",
        "\"",
        "}{",
        "END_IF",
        "PROGRAM",
        "PROGRAM P",
        "FUNCTION_BLOCK FB VAR x : ARRAY[1..",
        "CONFIGURATION C RESOURCE R ON",
        "x := 1;",
        "16#",
        "T#",
        "INT#",
        "%IX",
        "PROGRAM P x := 2#; y := 16#_; z := T#1.2.3s; END_PROGRAM",
        "PROGRAM P CASE x OF END_CASE; END_PROGRAM",
        "\xff\xfe\xfd",
        "PROGRAM P x := 'a\xff'; END_PROGRAM",
    };
    for (const std::string& input : inputs) {
        EXPECT_EQ(fuzz_one(input), 0) << input;
    }
}

// Each once crashed the compiler (exit 139 or 134); each now gives diagnostics or an image the
// loader accepts.
TEST(Robustness, InputsThatOnceCrashedTheCompilerCompileOrFailCleanly) {
    std::string nested = "TYPE S0 : STRUCT a, b : LWORD; END_STRUCT; END_TYPE\n";
    for (int level = 1; level <= 40; ++level) {
        nested += "TYPE S" + std::to_string(level) + " : STRUCT a, b : S" +
                  std::to_string(level - 1) + "; END_STRUCT; END_TYPE\n";
    }
    const std::string main = "PROGRAM Main VAR a : A; END_VAR END_PROGRAM";
    const std::string inputs[] = {
        "FUNCTION_BLOCK A VAR b : A; END_VAR END_FUNCTION_BLOCK " + main,
        "FUNCTION_BLOCK A VAR b : ARRAY[0..3] OF A; END_VAR END_FUNCTION_BLOCK " + main,
        "FUNCTION_BLOCK A VAR b : B; END_VAR END_FUNCTION_BLOCK "
        "FUNCTION_BLOCK B VAR a : A; END_VAR END_FUNCTION_BLOCK " +
            main,
        "FUNCTION_BLOCK A EXTENDS A END_FUNCTION_BLOCK " + main,
        "PROGRAM Main VAR a, b : ARRAY[0..40000000] OF DINT; END_VAR a[1] := 1; END_PROGRAM",
        "PROGRAM Main VAR a, b : ARRAY[0..10000000] OF DINT; END_VAR a[1] := b[2]; END_PROGRAM",
        nested + "PROGRAM Main VAR s : S40; END_VAR s.a.a.a.a.a := s.b.b.b.b.b; END_PROGRAM",
        "PROGRAM Main VAR s : STRING; END_VAR s := '" + std::string(65536, 'x') + "'; END_PROGRAM",
        "TYPE Node : STRUCT next : POINTER TO Node; END_STRUCT; END_TYPE "
        "PROGRAM Main VAR n : Node; END_VAR n.next := ADR(n); END_PROGRAM",
        "PROGRAM Main VAR x : DINT; END_VAR x := 1 / 0; END_PROGRAM",
    };
    for (const std::string& input : inputs) {
        EXPECT_EQ(fuzz_one(input), 0) << input.substr(0, 200);
    }
}

TEST(Robustness, RandomTokenSoupNeverCrashes) {
    const char* pieces[] = {
        "PROGRAM",    "END_PROGRAM", "IF",  "THEN", "END_IF",  "(",       ")",     "[",
        "]",          ":=",          ";",   ":",    "x",       "1",       "T#1s",  "'s'",
        "CASE",       "OF",          "..",  "VAR",  "END_VAR", "INT",     "ARRAY", "STRUCT",
        "END_STRUCT", "(*",          "*)",  "^",    ".",       "=>",      "NOT",   "-",
        "**",         ",",           "FOR", "TO",   "DO",      "END_FOR", "\n"};
    std::mt19937 random(20261122);
    std::uniform_int_distribution<std::size_t> pick(0, std::size(pieces) - 1);
    std::uniform_int_distribution<int> length(0, 60);
    for (int round = 0; round < 300; ++round) {
        std::string input;
        for (int i = length(random); i > 0; --i) {
            input += pieces[pick(random)];
            input += ' ';
        }
        EXPECT_EQ(fuzz_one(input), 0) << input;
    }
}

TEST(Robustness, DeepParenthesesAreRefusedBeforeParsing) {
    const test::Parsed parsed =
        parse_text("PROGRAM P x := " + std::string(100000, '(') + "1; END_PROGRAM");
    ASSERT_EQ(parsed.diagnostics.all().size(), 1u);
    EXPECT_EQ(parsed.first_message(), "nesting is deeper than 256 levels; simplify the code");
    EXPECT_EQ(parsed.diagnostics.all().front().range.begin.column, 16u + 256u);
}

TEST(Robustness, LongPrefixOperatorChainsAreRefused) {
    std::string nots;
    for (int i = 0; i < 50000; ++i) {
        nots += "NOT ";
    }
    EXPECT_EQ(parse_text("PROGRAM P x := " + nots + "y; END_PROGRAM").first_message(),
              "more than 256 operators or type constructors in a row");
    std::string refs;
    for (int i = 0; i < 50000; ++i) {
        refs += "REF_TO ";
    }
    EXPECT_EQ(parse_text("TYPE T : " + refs + "INT; END_TYPE").first_message(),
              "more than 256 operators or type constructors in a row");
}

TEST(Robustness, HugeStatementsAreRefused) {
    std::string sum = "x := 1";
    for (int i = 0; i < 100000; ++i) {
        sum += "+1";
    }
    EXPECT_EQ(parse_text("PROGRAM P " + sum + "; END_PROGRAM").first_message(),
              "more than 4096 operators in one statement; split it");
}

TEST(Robustness, ReasonableNestingStillParses) {
    std::string nested = "x := " + std::string(100, '(') + "1" + std::string(100, ')') + ";";
    for (int i = 0; i < 50; ++i) {
        nested = "IF c THEN " + nested + " END_IF;";
    }
    const test::Parsed parsed = parse_text("PROGRAM P " + nested + " END_PROGRAM");
    EXPECT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
}

TEST(Robustness, InvalidUtf8IsReportedWhereItIs) {
    const test::Parsed parsed = parse_text("PROGRAM P\n  x := 1; \xc3\x28\nEND_PROGRAM\n");
    ASSERT_FALSE(parsed.diagnostics.all().empty());
    const Diagnostic& first = parsed.diagnostics.all().front();
    EXPECT_EQ(first.message, "the file is not valid UTF-8 text here; it is read as Windows-1252, "
                             "as CODESYS exports it");
    EXPECT_EQ(first.severity, Severity::Warning);
    EXPECT_EQ(first.range.begin, (SourcePosition{2, 11}));
}

TEST(Robustness, UnterminatedCommentIsReportedOnce) {
    const test::Parsed parsed =
        parse_text("PROGRAM P\n  (* never closed\n  x := 1;\nEND_PROGRAM\n");
    ASSERT_EQ(parsed.diagnostics.all().size(), 1u);
    EXPECT_EQ(parsed.first_message(), "comment opened with '(*' is never closed");
    EXPECT_EQ(parsed.diagnostics.all().front().range.begin, (SourcePosition{2, 3}));
}

TEST(Robustness, LongProgramsParseCompletely) {
    std::string body;
    for (int i = 0; i < 5000; ++i) {
        body += "x := x + " + std::to_string(i) + ";\n";
    }
    const test::Parsed parsed =
        parse_text("PROGRAM P VAR x : DINT; END_VAR\n" + body + "END_PROGRAM");
    EXPECT_FALSE(parsed.diagnostics.has_errors());
    EXPECT_EQ(parsed.unit.pous.front().body.size(), 5000u);
}

} // namespace
} // namespace eposp::compiler
