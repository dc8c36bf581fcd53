#include "eposp/compiler/parser.hpp"

#include "../utf8.hpp"
#include "ascii_prefix.hpp"
#include "descent_parser.hpp"
#include "input_stream.hpp"
#include "lexer.hpp"
#include "nesting_limit.hpp"
#include "parse_tokens.hpp"
#include "source_token.hpp"
#include "syntax_error_strategy.hpp"
#include "token_range.hpp"

#include <atn/ParserATNSimulator.h>
#include <atn/PredictionMode.h>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace eposp::compiler {

namespace {

using generated::StructuredTextParser;

// The ANTLR runtime needs UTF-8. A file that is not, such as one exported from CODESYS with
// a 'ü' in a comment, is read as Windows-1252, one character a byte (so columns stay true),
// with one warning where the first byte that is not UTF-8 is.
std::string utf8_text(const SourceManager& sources, FileId file, Diagnostics& diagnostics) {
    const std::string& text = sources.text(file);
    if (ascii_prefix(text) == text.size()) {
        return text;
    }
    std::uint32_t line = 1;
    std::uint32_t column = 1;
    for (std::size_t position = 0; position < text.size();) {
        // ASCII, nearly every byte, needs no call.
        const std::optional<char32_t> code_point =
            static_cast<unsigned char>(text[position]) < 0x80
                ? std::optional<char32_t>(static_cast<char32_t>(text[position++]))
                : utf8::decode(text, position);
        if (!code_point) {
            diagnostics.warning(DiagnosticCode::W0104, {file, {line, column}, {line, column}},
                                "the file is not valid UTF-8 text here; it is read as "
                                "Windows-1252, as CODESYS exports it");
            return utf8::from_windows_1252(text);
        }
        if (code_point == U'\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return text;
}

// Lexical errors, reported before parsing. An unclosed comment lexes as '(' '*' (or '/' '*')
// with nothing between, a pair that no ST construct contains; everything after it is comment
// text, so the file is not parsed further. An unclosed string ends at the end of its line.
bool report_lexical_errors(const std::vector<antlr4::Token*>& all, FileId file,
                           Diagnostics& diagnostics) {
    for (std::size_t i = 0; i < all.size(); ++i) {
        const std::size_t type = all[i]->getType();
        if (type == StructuredTextParser::UNTERMINATED_STRING) {
            diagnostics.error(DiagnosticCode::E0102, token_range(file, *all[i]),
                              std::string("missing closing ") + all[i]->getText().front() +
                                  " at the end of this string");
            continue;
        }
        if ((type == StructuredTextParser::LEFT_PAREN || type == StructuredTextParser::SLASH) &&
            i + 1 < all.size() && all[i + 1]->getType() == StructuredTextParser::STAR &&
            all[i + 1]->getStartIndex() == all[i]->getStartIndex() + 1) {
            diagnostics.error(DiagnosticCode::E0103, token_range(file, *all[i], *all[i + 1]),
                              "comment opened with '" + all[i]->getText() + "*' is never closed");
            return false;
        }
    }
    return true;
}

// The file's tokens have been parsed up to `refused` by the hand-written parser; the generated
// one reports the syntax error there (none after an unterminated string, already reported).
// Should the file have no error at all, the hand-written parser refused what the grammar
// accepts: a fault of ours, reported as such rather than left without a message.
void report_syntax_errors(antlr4::CommonTokenStream& tokens, const antlr4::Token& refused,
                          FileId file, Diagnostics& diagnostics, std::size_t errors_before) {
    StructuredTextParser parser(&tokens);
    parse_with_recovery(parser, file, diagnostics);
    if (diagnostics.error_count() == errors_before) {
        diagnostics.error(DiagnosticCode::E0001, token_range(file, refused),
                          "internal error: the parser refused this token, which the grammar "
                          "accepts here (the generated parser found no syntax error)");
    }
}

} // namespace

bool check_tokens(const std::vector<antlr4::Token*>& tokens, FileId file,
                  Diagnostics& diagnostics) {
    return report_lexical_errors(tokens, file, diagnostics) &&
           check_nesting(tokens, file, diagnostics);
}

StructuredTextParser::CompilationUnitContext*
parse_with_recovery(StructuredTextParser& parser, FileId file, Diagnostics& diagnostics) {
    parser.reset(); // from the first token
    parser.removeErrorListeners();
    parser.setErrorHandler(std::make_shared<SyntaxErrorStrategy>(file, diagnostics));
    parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(
        antlr4::atn::PredictionMode::LL);
    return parser.compilationUnit();
}

namespace {

// The whole file's tokens are read first: the lexical checks and limits see them all before
// anything is parsed. `stream` makes the token stream of the same tokens that the generated
// parser reports syntax errors from, when the hand-written parser refuses them.
ast::CompilationUnit parse_all(const std::vector<antlr4::Token*>& all, FileId file,
                               Diagnostics& diagnostics,
                               const std::function<antlr4::CommonTokenStream&()>& stream) {
    const std::size_t errors_before = diagnostics.error_count();
    if (!check_tokens(all, file, diagnostics)) {
        return ast::CompilationUnit{file, nullptr, {}, {}, {}, {}};
    }
    // What the parser says is kept apart until the file is known to parse.
    Diagnostics built(std::numeric_limits<std::size_t>::max());
    DescentParser parser(all, file, built);
    std::optional<ast::CompilationUnit> unit = parser.compilation_unit();
    if (!unit) {
        report_syntax_errors(stream(), *parser.refused_at(), file, diagnostics, errors_before);
        return ast::CompilationUnit{file, nullptr, {}, {}, {}, {}};
    }
    if (diagnostics.error_count() != errors_before) {
        return ast::CompilationUnit{file, nullptr, {}, {}, {}, {}};
    }
    for (const Diagnostic& diagnostic : built.all()) {
        diagnostics.report(diagnostic);
    }
    return std::move(*unit);
}

// The hand-written lexer's tokens are made as values: the token stream would
// make each a heap object, find its type with a dynamic_cast and free it at the end, which cost
// as much as lexing itself. The stream is made, by lexing again, only for the generated parser.
ast::CompilationUnit parse_lexed(Lexer& lexer, FileId file, Diagnostics& diagnostics) {
    std::vector<std::vector<SourceToken>> blocks = lexer.all_tokens();
    std::vector<antlr4::Token*> all;
    all.reserve(blocks.size() * blocks.front().capacity());
    for (std::vector<SourceToken>& block : blocks) {
        for (SourceToken& token : block) {
            all.push_back(&token);
        }
    }
    std::optional<Lexer> again;
    std::optional<antlr4::CommonTokenStream> stream;
    return parse_all(all, file, diagnostics, [&]() -> antlr4::CommonTokenStream& {
        again.emplace(lexer.input());
        stream.emplace(&*again);
        return *stream;
    });
}

} // namespace

ast::CompilationUnit parse_tokens(antlr4::TokenSource& source, FileId file,
                                  Diagnostics& diagnostics) {
    if (auto* lexer = dynamic_cast<Lexer*>(&source)) {
        return parse_lexed(*lexer, file, diagnostics);
    }
    antlr4::CommonTokenStream tokens(&source);
    tokens.fill();
    return parse_all(tokens.getTokens(), file, diagnostics,
                     [&]() -> antlr4::CommonTokenStream& { return tokens; });
}

ast::CompilationUnit parse(const SourceManager& sources, FileId file, Diagnostics& diagnostics) {
    const std::string text = utf8_text(sources, file, diagnostics);
    InputStream input(text);
    Lexer lexer(input);
    return parse_lexed(lexer, file, diagnostics);
}

} // namespace eposp::compiler
