#include "syntax_error_strategy.hpp"

#include "StructuredTextParser.h"
#include "token_range.hpp"

#include <FailedPredicateException.h>
#include <InputMismatchException.h>
#include <NoViableAltException.h>
#include <Parser.h>
#include <string>
#include <vector>

namespace eposp::compiler {

namespace {

using generated::StructuredTextParser;

// Tokens that can start an expression or a statement: sets containing them are summarised as
// "an expression" / "a statement" instead of being listed.
constexpr std::size_t kExpressionStarts[] = {
    StructuredTextParser::IDENTIFIER,
    StructuredTextParser::INTEGER,
    StructuredTextParser::BASED_INTEGER,
    StructuredTextParser::REAL_LITERAL,
    StructuredTextParser::TRUE,
    StructuredTextParser::FALSE,
    StructuredTextParser::NULL_REFERENCE,
    StructuredTextParser::STRING_LITERAL,
    StructuredTextParser::WSTRING_LITERAL,
    StructuredTextParser::UNTERMINATED_STRING,
    StructuredTextParser::TIME_LITERAL,
    StructuredTextParser::DATE_LITERAL,
    StructuredTextParser::TIME_OF_DAY_LITERAL,
    StructuredTextParser::DATE_AND_TIME_LITERAL,
    StructuredTextParser::TYPED_LITERAL,
    StructuredTextParser::LEFT_PAREN,
    StructuredTextParser::MINUS,
    StructuredTextParser::PLUS,
    StructuredTextParser::NOT,
    StructuredTextParser::MOD, // MOD, AND, OR and XOR start a call of them: MOD(a, b)
    StructuredTextParser::AND,
    StructuredTextParser::OR,
    StructuredTextParser::XOR,
    StructuredTextParser::REF,
    StructuredTextParser::DIRECT_ADDRESS,
};
constexpr std::size_t kStatementStarts[] = {
    StructuredTextParser::IF,       StructuredTextParser::CASE,   StructuredTextParser::FOR,
    StructuredTextParser::WHILE,    StructuredTextParser::REPEAT, StructuredTextParser::EXIT,
    StructuredTextParser::CONTINUE, StructuredTextParser::RETURN, StructuredTextParser::SEMICOLON,
};
constexpr std::size_t kMaxListed = 4;

template <std::size_t n>
bool contains_all(const antlr4::misc::IntervalSet& set, const std::size_t (&tokens)[n]) {
    for (std::size_t token : tokens) {
        if (!set.contains(token)) {
            return false;
        }
    }
    return true;
}

template <std::size_t n>
bool is_one_of(std::size_t token, const std::size_t (&tokens)[n]) {
    for (std::size_t candidate : tokens) {
        if (candidate == token) {
            return true;
        }
    }
    return false;
}

// How a token type is named in "expected ..." messages.
std::string expected_name(const antlr4::dfa::Vocabulary& vocabulary, std::size_t type) {
    switch (type) {
    case antlr4::Token::EOF:
        return "end of file";
    case StructuredTextParser::IDENTIFIER:
        return "a name";
    case StructuredTextParser::INTEGER:
        return "an integer";
    case StructuredTextParser::DIRECT_ADDRESS:
        return "a direct address such as %IX0.0";
    case StructuredTextParser::NULL_REFERENCE:
        return "'NULL'";
    default:
        break;
    }
    const std::string literal = vocabulary.getLiteralName(type);
    return literal.empty() ? "'" + vocabulary.getSymbolicName(type) + "'" : literal;
}

std::string join_alternatives(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) {
            out += i + 1 == items.size() ? " or " : ", ";
        }
        out += items[i];
    }
    return out;
}

// "a statement or 'END_IF'", "an expression", "';'"; empty when the set is too large to help.
std::string describe_expected(const antlr4::dfa::Vocabulary& vocabulary,
                              const antlr4::misc::IntervalSet& expected) {
    const bool statement = contains_all(expected, kStatementStarts);
    const bool expression = !statement && contains_all(expected, kExpressionStarts);
    std::vector<std::string> items;
    if (statement) {
        items.push_back("a statement");
    }
    if (expression) {
        items.push_back("an expression");
    }
    for (ssize_t token : expected.toList()) {
        const auto type = static_cast<std::size_t>(token);
        if ((statement &&
             (is_one_of(type, kStatementStarts) || is_one_of(type, kExpressionStarts))) ||
            (expression && is_one_of(type, kExpressionStarts))) {
            continue;
        }
        if (token == static_cast<ssize_t>(antlr4::Token::EPSILON)) {
            continue;
        }
        if (type == StructuredTextParser::ON &&
            expected.contains(static_cast<ssize_t>(StructuredTextParser::IDENTIFIER))) {
            continue; // ON is a name outside a RESOURCE declaration: "a name" says it
        }
        items.push_back(expected_name(vocabulary, type));
    }
    if (items.empty() || items.size() > kMaxListed) {
        return "";
    }
    return join_alternatives(items);
}

// How the offending token is quoted in messages.
std::string found_name(const antlr4::Token& token) {
    if (token.getType() == antlr4::Token::EOF) {
        return "end of file";
    }
    return "'" + token.getText() + "'";
}

// What a ';' ends, from the rule being parsed: "expected ';' after statement".
std::string_view what_semicolon_ends(antlr4::ParserRuleContext* context) {
    if (context == nullptr) {
        return {};
    }
    switch (context->getRuleIndex()) {
    case StructuredTextParser::RuleStatement:
        return "statement";
    case StructuredTextParser::RuleVarDeclaration:
    case StructuredTextParser::RuleAccessDeclaration:
        return "declaration";
    case StructuredTextParser::RuleTypeDeclaration:
        return "type declaration";
    case StructuredTextParser::RuleTaskDeclaration:
        return "task declaration";
    case StructuredTextParser::RuleProgramConfiguration:
        return "program configuration";
    default:
        return {};
    }
}

// An unterminated string swallows the rest of its line, ';' included: what the parser then
// misses is a consequence of the error already reported for the string.
bool follows_unterminated_string(antlr4::Parser* parser) {
    const antlr4::Token* previous = parser->getTokenStream()->LT(-1);
    return previous != nullptr && previous->getType() == StructuredTextParser::UNTERMINATED_STRING;
}

bool closes_a_block(std::size_t token) {
    switch (token) {
    case StructuredTextParser::END_IF:
    case StructuredTextParser::END_CASE:
    case StructuredTextParser::END_FOR:
    case StructuredTextParser::END_WHILE:
    case StructuredTextParser::END_REPEAT:
    case StructuredTextParser::END_VAR:
    case StructuredTextParser::END_STRUCT:
    case StructuredTextParser::END_TYPE:
    case StructuredTextParser::END_FUNCTION:
    case StructuredTextParser::END_FUNCTION_BLOCK:
    case StructuredTextParser::END_PROGRAM:
    case StructuredTextParser::END_RESOURCE:
    case StructuredTextParser::END_CONFIGURATION:
        return true;
    default:
        return false;
    }
}

} // namespace

SyntaxErrorStrategy::SyntaxErrorStrategy(FileId file, Diagnostics& diagnostics)
    : file_(file), diagnostics_(diagnostics) {}

void SyntaxErrorStrategy::report_unexpected(antlr4::Parser* parser, antlr4::Token* token,
                                            const antlr4::misc::IntervalSet& expected) {
    if (follows_unterminated_string(parser)) {
        return;
    }
    const std::string description = describe_expected(parser->getVocabulary(), expected);
    std::string message;
    if (token->getType() == StructuredTextParser::INVALID_CHARACTER) {
        message = "unexpected character " + found_name(*token);
    } else if (description.empty()) {
        message = "unexpected " + found_name(*token);
    } else {
        message = "expected " + description + ", found " + found_name(*token);
    }
    diagnostics_.error(DiagnosticCode::E0101, token_range(file_, *token), std::move(message));
}

void SyntaxErrorStrategy::reportNoViableAlternative(antlr4::Parser* parser,
                                                    const antlr4::NoViableAltException& error) {
    report_unexpected(parser, error.getOffendingToken(), error.getExpectedTokens());
}

void SyntaxErrorStrategy::reportInputMismatch(antlr4::Parser* parser,
                                              const antlr4::InputMismatchException& error) {
    report_unexpected(parser, error.getOffendingToken(), error.getExpectedTokens());
}

void SyntaxErrorStrategy::reportFailedPredicate(antlr4::Parser* parser,
                                                const antlr4::FailedPredicateException& error) {
    report_unexpected(parser, error.getOffendingToken(), error.getExpectedTokens());
}

void SyntaxErrorStrategy::reportUnwantedToken(antlr4::Parser* parser) {
    if (inErrorRecoveryMode(parser)) {
        return;
    }
    beginErrorCondition(parser);
    if (follows_unterminated_string(parser)) {
        return;
    }
    antlr4::Token* token = parser->getCurrentToken();
    const std::string message = token->getType() == StructuredTextParser::INVALID_CHARACTER
                                    ? "unexpected character " + found_name(*token)
                                    : "unexpected " + found_name(*token);
    const std::string description =
        describe_expected(parser->getVocabulary(), getExpectedTokens(parser));
    diagnostics_.error(DiagnosticCode::E0101, token_range(file_, *token),
                       description.empty() ? message : message + "; expected " + description);
}

// Dropping a block's closing keyword because the token after it fits (`x := 1 END_IF;`) would
// leave the block open and cascade into errors up to the end of the file; the better guess is
// that something is missing before the keyword.
antlr4::Token* SyntaxErrorStrategy::singleTokenDeletion(antlr4::Parser* parser) {
    if (closes_a_block(parser->getCurrentToken()->getType())) {
        return nullptr;
    }
    return DefaultErrorStrategy::singleTokenDeletion(parser);
}

void SyntaxErrorStrategy::reportMissingToken(antlr4::Parser* parser) {
    if (inErrorRecoveryMode(parser)) {
        return;
    }
    beginErrorCondition(parser);
    if (follows_unterminated_string(parser)) {
        return;
    }
    const antlr4::misc::IntervalSet expected = getExpectedTokens(parser);
    const std::string description = describe_expected(parser->getVocabulary(), expected);
    std::string message = description.empty()
                              ? "unexpected " + found_name(*parser->getCurrentToken())
                              : "expected " + description;
    const std::string_view ends = what_semicolon_ends(parser->getContext());
    if (expected.size() == 1 && expected.contains(std::size_t{StructuredTextParser::SEMICOLON}) &&
        !ends.empty()) {
        message += " after " + std::string(ends);
    }
    // The missing token belongs right after the previous one, not on the next line.
    antlr4::Token* previous = parser->getTokenStream()->LT(-1);
    const SourceRange range = previous != nullptr ? range_after(file_, *previous)
                                                  : token_range(file_, *parser->getCurrentToken());
    diagnostics_.error(DiagnosticCode::E0101, range, std::move(message));
}

} // namespace eposp::compiler
