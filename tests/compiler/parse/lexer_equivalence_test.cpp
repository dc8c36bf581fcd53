// The hand-written lexer (compiler/src/parse/lexer.cpp) against the one ANTLR generates from the
// grammar's lexer rules, its oracle: the same tokens (type, channel, text, start and stop index,
// line, column) and, parsed on from each, the same AST and diagnostics, for every ST file of the
// repository and of the benchmarks, and for inputs generated here from a fixed seed: random
// bytes, truncations and mutations of the files, every keyword in mixed case, nested comments,
// pragmas and every literal form of the grammar, whole and cut short.
#include "StructuredTextLexer.h"
#include "eposp/compiler/ast/ast_printer.hpp"
#include "eposp/compiler/source_manager.hpp"
#include "parse/input_stream.hpp"
#include "parse/lexer.hpp"
#include "parse/parse_tokens.hpp"
#include "st_corpus.hpp"

#include <CommonTokenStream.h>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace eposp::compiler {
namespace {

using generated::StructuredTextLexer;

// Every token the source yields up to and including EOF, a line each.
std::vector<std::string> tokens_of(antlr4::TokenSource& source) {
    std::vector<std::string> lines;
    for (;;) {
        const std::unique_ptr<antlr4::Token> token = source.nextToken();
        std::ostringstream line;
        line << static_cast<long long>(token->getType()) << " channel " << token->getChannel()
             << " [" << static_cast<long long>(token->getStartIndex()) << ".."
             << static_cast<long long>(token->getStopIndex()) << "] " << token->getLine() << ':'
             << token->getCharPositionInLine() << " '" << token->getText() << "'";
        lines.push_back(line.str());
        if (token->getType() == antlr4::Token::EOF) {
            return lines;
        }
    }
}

// The AST and every diagnostic of the file parsed from the tokens of `lexer`.
template <typename MakeLexer>
std::string parsed_with(const std::string& text, MakeLexer make_lexer) {
    SourceManager sources;
    const FileId file = sources.add("input.st", text);
    Diagnostics diagnostics;
    InputStream input(text);
    auto lexer = make_lexer(input);
    const ast::CompilationUnit unit = parse_tokens(*lexer, file, diagnostics);
    return ast::to_sexpr(unit) + "\n" + render(diagnostics, sources);
}

std::unique_ptr<antlr4::TokenSource> generated_lexer(InputStream& input) {
    auto lexer = std::make_unique<StructuredTextLexer>(&input);
    lexer->removeErrorListeners(); // as the parser used it: INVALID_CHARACTER catches all
    return lexer;
}

std::unique_ptr<antlr4::TokenSource> hand_written_lexer(InputStream& input) {
    return std::make_unique<Lexer>(input);
}

// Both lexers on one input; `parse` also compares the ASTs and diagnostics parsed from them.
void expect_same(const std::string& bytes, const std::string& name, bool parse = true) {
    if (::testing::Test::HasFailure()) {
        return; // the first difference of a test says enough
    }
    SCOPED_TRACE(name);
    const std::string text = corpus::as_text(bytes);
    // The input stream decodes the text itself, as the runtime's would.
    ASSERT_EQ(InputStream(text).toString(), antlr4::ANTLRInputStream(text).toString());
    InputStream generated_input(text);
    InputStream hand_written_input(text);
    const auto expected = tokens_of(*generated_lexer(generated_input));
    const auto actual = tokens_of(*hand_written_lexer(hand_written_input));
    ASSERT_EQ(expected, actual) << "input: " << text;
    // The hand-written lexer numbers its tokens itself, as the token stream would.
    InputStream numbered_input(text);
    Lexer numbered(numbered_input);
    antlr4::CommonTokenStream stream(&numbered);
    stream.fill();
    for (std::size_t i = 0; i < stream.size(); ++i) {
        ASSERT_EQ(stream.get(i)->getTokenIndex(), i) << "input: " << text;
    }
    if (parse) {
        ASSERT_EQ(parsed_with(text, generated_lexer), parsed_with(text, hand_written_lexer))
            << "input: " << text;
    }
}

TEST(LexerEquivalence, EveryStFileOfTheRepositoryAndTheBenchmarks) {
    const auto files = corpus::st_files();
    ASSERT_GE(files.size(), 60U);
    for (const auto& file : files) {
        expect_same(corpus::read_file(file), file.string());
    }
}

TEST(LexerEquivalence, TruncatedAndMutatedFiles) {
    std::mt19937 random(17);
    for (const auto& file : corpus::st_files()) {
        corpus::for_each_variant(corpus::read_file(file), file.string(), random,
                                 corpus::kInteresting,
                                 [](const std::string& text, const std::string& name) {
                                     expect_same(text, name);
                                 });
    }
}

TEST(LexerEquivalence, RandomBytes) {
    std::mt19937 random(61131);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int i = 0; i < 2000; ++i) {
        std::string bytes;
        const std::size_t length = random() % 64;
        for (std::size_t j = 0; j < length; ++j) {
            bytes.push_back(static_cast<char>(byte(random)));
        }
        expect_same(bytes, "random bytes " + std::to_string(i));
    }
}

TEST(LexerEquivalence, RandomTextOfTheCharactersThatMatter) {
    std::mt19937 random(3);
    for (int i = 0; i < 20000; ++i) {
        const std::string text = corpus::random_string(random, corpus::kInteresting, random() % 40);
        expect_same(text, "random text " + std::to_string(i), i % 10 == 0);
    }
}

TEST(LexerEquivalence, EveryKeywordInMixedCase) {
    std::mt19937 random(4);
    InputStream empty("");
    const antlr4::dfa::Vocabulary& vocabulary = StructuredTextLexer(&empty).getVocabulary();
    const std::string after[] = {"", " ", "1", "_", "x", "#", "#1", "#x", "#'s'", "(", ";"};
    for (std::size_t type = StructuredTextLexer::TYPE; type <= StructuredTextLexer::NULL_REFERENCE;
         ++type) {
        std::string word = vocabulary.getSymbolicName(type);
        if (type == StructuredTextLexer::NULL_REFERENCE) {
            word = "NULL";
        }
        for (const std::string& suffix : after) {
            for (const std::string& spelling :
                 {word, corpus::mixed_case(random, word), corpus::mixed_case(random, word)}) {
                expect_same(spelling + suffix, spelling + suffix);
                expect_same("x" + spelling + suffix, "x" + spelling + suffix, false);
            }
        }
    }
}

TEST(LexerEquivalence, EveryShortTextOfCommentCharacters) {
    // All texts of up to five characters after an opening "(*" or "/*", of both comments'
    // characters: nesting, closing early, closing never.
    const std::string alphabet = "(*)/x\n";
    for (const std::string opening : {"(*", "/*"}) {
        std::vector<std::string> texts{""};
        for (std::size_t length = 0; length < 5; ++length) {
            std::vector<std::string> longer;
            for (const std::string& text : texts) {
                for (const char c : alphabet) {
                    longer.push_back(text + c);
                }
            }
            for (const std::string& text : longer) {
                expect_same(opening + text, opening + text, false);
            }
            texts = std::move(longer);
        }
    }
}

TEST(LexerEquivalence, NestedCommentsAndPragmas) {
    std::mt19937 random(5);
    const std::string pieces[] = {"(*", "*)", "/*", "*/",   "(", ")", "*", "/",  "//",  "{",
                                  "}",  "x",  "\n", "\r\n", " ", "'", "$", "**", "*)*)"};
    std::uniform_int_distribution<std::size_t> pick(0, std::size(pieces) - 1);
    for (int i = 0; i < 4000; ++i) {
        std::string text = random() % 2 == 0 ? "(*" : "/*";
        const std::size_t count = random() % 14;
        for (std::size_t j = 0; j < count; ++j) {
            text += pieces[pick(random)];
        }
        expect_same(text + " x := 1;", "comment " + std::to_string(i), i % 8 == 0);
    }
    for (const std::string text :
         {"{attribute 'hide'} x", "{ a\nb } y", "{ never closed", "{}", "{{}}", "x{y}z",
          "(* a (* b *) c *) d", "(* a (* b *) c", "/* a /* b */ c */ d", "/* (* */ *)",
          "(* /* *) */", "// line (* \n x", "//\r\n", "(*)", "(**)", "(***)", "/**/", "/*/"}) {
        expect_same(text, text);
    }
}

TEST(LexerEquivalence, EveryLiteralFormWholeAndCutShort) {
    const std::string literals[] = {"0",
                                    "42",
                                    "1_000",
                                    "16#FF",
                                    "2#1010_1010",
                                    "8#777",
                                    "16#",
                                    "1#",
                                    "1.5",
                                    "1.5E10",
                                    "1.5e-3",
                                    "1.5e+3",
                                    "1e5",
                                    "1E",
                                    "1e+",
                                    "1.",
                                    "1..5",
                                    "1.e5",
                                    "3.14_15",
                                    "INT#16#FF",
                                    "INT#-5",
                                    "INT#+5",
                                    "INT#-",
                                    "REAL#1.5",
                                    "REAL#1.5e-3",
                                    "REAL#1e3",
                                    "LREAL#-1.0E+2",
                                    "BOOL#TRUE",
                                    "BOOL#1",
                                    "STRING#'x'",
                                    "WSTRING#\"x\"",
                                    "STRING#'",
                                    "Color#Red",
                                    "Color#",
                                    "_x#y",
                                    "T#5s",
                                    "t#1h2m3s4ms",
                                    "TIME#-1.5h",
                                    "T#+1d",
                                    "LT#1d2h",
                                    "LTIME#5us",
                                    "T#",
                                    "T#s",
                                    "TIME#1_000ms",
                                    "T#1.5.5",
                                    "D#2020-01-01",
                                    "DATE#2020-1-1",
                                    "LD#2020-01-01",
                                    "LDATE#1970-01-01",
                                    "D#",
                                    "TOD#12:00:00.5",
                                    "TIME_OF_DAY#1:2:3",
                                    "LTOD#23:59:59.999",
                                    "LTIME_OF_DAY#00:00",
                                    "TOD#",
                                    "DT#2020-01-01-12:00:00",
                                    "DATE_AND_TIME#2020-01-01-0:0",
                                    "LDT#1970-01-01-00:00:00.1",
                                    "LDATE_AND_TIME#2000-2-2-2:2:2",
                                    "DT#x",
                                    "'a$'b'",
                                    "'$N$L$R$T$P$$$''",
                                    "'$41'",
                                    "'abc",
                                    "'$",
                                    "'",
                                    "''",
                                    "\"wide$\"\"",
                                    "\"$0041\"",
                                    "\"open",
                                    "\"",
                                    "'a\"b'",
                                    "\"a'b\"",
                                    "'line\nbreak'",
                                    "'dollar$\nbreak'",
                                    "%IX1.2",
                                    "%QW7",
                                    "%MD3.4.5",
                                    "%I*",
                                    "%IX",
                                    "%X1",
                                    "%i1",
                                    "%QB0.",
                                    "%ML1..2",
                                    "%",
                                    "TRUE",
                                    "FALSE",
                                    "NULL",
                                    "x.1",
                                    "a.b.c",
                                    "a..b",
                                    "a:=b",
                                    "a=>b",
                                    "a<=b",
                                    "a>=b",
                                    "a<>b",
                                    "a**b",
                                    "a^",
                                    "a&b",
                                    "ä",
                                    "x€y",
                                    "\x7f",
                                    "#",
                                    "$",
                                    "!",
                                    "?",
                                    "@",
                                    "~",
                                    "`",
                                    "\\",
                                    "|",
                                    "\f",
                                    "\v",
                                    std::string("\0x", 2),
                                    "\xEF\xBB\xBFx",
                                    "x\xEF\xBB\xBF"};
    for (const std::string& literal : literals) {
        for (std::size_t length = 0; length <= literal.size(); ++length) {
            const std::string cut = literal.substr(0, length);
            for (const std::string& around : {cut, "x := " + cut + ";", cut + cut, cut + "#1"}) {
                expect_same(around, around, length == literal.size());
            }
        }
    }
}

} // namespace
} // namespace eposp::compiler
