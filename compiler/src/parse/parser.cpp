#include "eposp/compiler/parser.hpp"

#include "../utf8.hpp"
#include "StructuredTextParser.h"
#include "ast_builder.hpp"
#include "input_stream.hpp"
#include "lexer.hpp"
#include "nesting_limit.hpp"
#include "parse_tokens.hpp"
#include "syntax_error_strategy.hpp"
#include "token_range.hpp"

#include <BailErrorStrategy.h>
#include <CommonTokenStream.h>
#include <Exceptions.h>
#include <atn/ParserATNSimulator.h>
#include <atn/PredictionMode.h>
#include <limits>
#include <memory>
#include <optional>

namespace eposp::compiler {

namespace {

using generated::StructuredTextParser;

// The ANTLR runtime needs UTF-8. A file that is not, such as one exported from CODESYS with
// a 'ü' in a comment, is read as Windows-1252, one character a byte (so columns stay true),
// with one warning where the first byte that is not UTF-8 is.
std::string utf8_text(const SourceManager& sources, FileId file, Diagnostics& diagnostics) {
    const std::string& text = sources.text(file);
    std::uint32_t line = 1;
    std::uint32_t column = 1;
    for (std::size_t position = 0; position < text.size();) {
        const std::optional<char32_t> code_point = utf8::decode(text, position);
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
bool report_lexical_errors(antlr4::CommonTokenStream& tokens, FileId file,
                           Diagnostics& diagnostics) {
    const std::vector<antlr4::Token*>& all = tokens.getTokens();
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

void set_prediction_mode(StructuredTextParser& parser, antlr4::atn::PredictionMode mode) {
    parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(mode);
}

// Correct input (nearly all) parses with the fast SLL prediction, bailing out on the first
// error. It is parsed one library element at a time, each element's parse tree turned into its
// AST and freed before the next: the tree of a whole file takes many times the memory of its
// AST. The builder reports to `built`, kept apart until the file is known to parse.
std::optional<ast::CompilationUnit> parse_elements(StructuredTextParser& parser,
                                                   antlr4::CommonTokenStream& tokens, FileId file,
                                                   Diagnostics& built) {
    parser.removeErrorListeners();
    parser.setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
    set_prediction_mode(parser, antlr4::atn::PredictionMode::SLL);
    AstBuilder builder(tokens, file, built);
    ast::CompilationUnit unit{file, {}, {}, {}, {}};
    try {
        while (tokens.LA(1) != antlr4::Token::EOF) {
            builder.library_element(*parser.libraryElement(), unit);
            parser.getTreeTracker().reset();
        }
    } catch (const antlr4::ParseCancellationException&) {
        return std::nullopt;
    }
    return unit;
}

// Only when the fast parse fails is the file parsed again, whole, with full LL prediction and
// error recovery, which also decides whether the error is real. No AST when it is.
std::optional<ast::CompilationUnit> parse_with_recovery(StructuredTextParser& parser,
                                                        antlr4::CommonTokenStream& tokens,
                                                        FileId file, Diagnostics& diagnostics,
                                                        Diagnostics& built) {
    const std::size_t errors_before = diagnostics.error_count();
    tokens.seek(0);
    parser.reset();
    parser.setErrorHandler(std::make_shared<SyntaxErrorStrategy>(file, diagnostics));
    set_prediction_mode(parser, antlr4::atn::PredictionMode::LL);
    StructuredTextParser::CompilationUnitContext* tree = parser.compilationUnit();
    if (diagnostics.error_count() != errors_before) {
        return std::nullopt;
    }
    return build_ast(*tree, tokens, file, built);
}

} // namespace

ast::CompilationUnit parse_tokens(antlr4::TokenSource& lexer, FileId file,
                                  Diagnostics& diagnostics) {
    const std::size_t errors_before = diagnostics.error_count();
    antlr4::CommonTokenStream tokens(&lexer);
    tokens.fill();
    if (!report_lexical_errors(tokens, file, diagnostics) ||
        !check_nesting(tokens.getTokens(), file, diagnostics)) {
        return ast::CompilationUnit{file, {}, {}, {}, {}};
    }
    StructuredTextParser parser(&tokens);
    const auto unlimited = std::numeric_limits<std::size_t>::max();
    Diagnostics built(unlimited);
    std::optional<ast::CompilationUnit> unit = parse_elements(parser, tokens, file, built);
    if (!unit) {
        built = Diagnostics(unlimited); // what the builder said before the syntax error
        unit = parse_with_recovery(parser, tokens, file, diagnostics, built);
    }
    if (!unit || diagnostics.error_count() != errors_before) {
        return ast::CompilationUnit{file, {}, {}, {}, {}};
    }
    for (const Diagnostic& diagnostic : built.all()) {
        diagnostics.report(diagnostic);
    }
    return std::move(*unit);
}

ast::CompilationUnit parse(const SourceManager& sources, FileId file, Diagnostics& diagnostics) {
    const std::string text = utf8_text(sources, file, diagnostics);
    InputStream input(text);
    Lexer lexer(input);
    return parse_tokens(lexer, file, diagnostics);
}

} // namespace eposp::compiler
