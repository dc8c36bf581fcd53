#include "ast_builder.hpp"
#include "parse_tokens.hpp"

#include <BailErrorStrategy.h>
#include <Exceptions.h>
#include <atn/ParserATNSimulator.h>
#include <atn/PredictionMode.h>
#include <limits>
#include <memory>
#include <optional>

namespace eposp::compiler {

namespace {

using generated::StructuredTextParser;

// Correct input parses with the fast SLL prediction, bailing out on the first error, one library
// element at a time. The builder reports to `built`, kept apart until the file is known to parse.
std::optional<ast::CompilationUnit> parse_elements(StructuredTextParser& parser,
                                                   antlr4::CommonTokenStream& tokens, FileId file,
                                                   Diagnostics& built) {
    parser.removeErrorListeners();
    parser.setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
    parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(
        antlr4::atn::PredictionMode::SLL);
    AstBuilder builder(tokens, file, built);
    ast::CompilationUnit unit = builder.unit();
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

} // namespace

ast::CompilationUnit parse_tokens_with_tree(antlr4::TokenSource& lexer, FileId file,
                                            Diagnostics& diagnostics) {
    const std::size_t errors_before = diagnostics.error_count();
    antlr4::CommonTokenStream tokens(&lexer);
    tokens.fill();
    if (!check_tokens(tokens.getTokens(), file, diagnostics)) {
        return ast::CompilationUnit{file, nullptr, {}, {}, {}, {}};
    }
    StructuredTextParser parser(&tokens);
    const auto unlimited = std::numeric_limits<std::size_t>::max();
    Diagnostics built(unlimited);
    std::optional<ast::CompilationUnit> unit = parse_elements(parser, tokens, file, built);
    if (!unit) {
        built = Diagnostics(unlimited); // what the builder said before the syntax error
        const std::size_t errors_before_parse = diagnostics.error_count();
        StructuredTextParser::CompilationUnitContext* tree =
            parse_with_recovery(parser, file, diagnostics);
        if (diagnostics.error_count() == errors_before_parse) {
            unit = build_ast(*tree, tokens, file, built);
        }
    }
    if (!unit || diagnostics.error_count() != errors_before) {
        return ast::CompilationUnit{file, nullptr, {}, {}, {}, {}};
    }
    for (const Diagnostic& diagnostic : built.all()) {
        diagnostics.report(diagnostic);
    }
    return std::move(*unit);
}

} // namespace eposp::compiler
