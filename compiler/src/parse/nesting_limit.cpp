#include "nesting_limit.hpp"

#include "StructuredTextLexer.h"
#include "token_range.hpp"

namespace eposp::compiler {

namespace {

using generated::StructuredTextLexer;

enum class Role { Other, Opens, Closes, Prefix, TypePrefix, Binary, EndsStatement };

Role role_of(std::size_t type) {
    switch (type) {
    case StructuredTextLexer::LEFT_PAREN:
    case StructuredTextLexer::LEFT_BRACKET:
    case StructuredTextLexer::IF:
    case StructuredTextLexer::CASE:
    case StructuredTextLexer::FOR:
    case StructuredTextLexer::WHILE:
    case StructuredTextLexer::REPEAT:
    case StructuredTextLexer::STRUCT:
        return Role::Opens;
    case StructuredTextLexer::RIGHT_PAREN:
    case StructuredTextLexer::RIGHT_BRACKET:
    case StructuredTextLexer::END_IF:
    case StructuredTextLexer::END_CASE:
    case StructuredTextLexer::END_FOR:
    case StructuredTextLexer::END_WHILE:
    case StructuredTextLexer::END_REPEAT:
    case StructuredTextLexer::END_STRUCT:
        return Role::Closes;
    case StructuredTextLexer::NOT:
        return Role::Prefix;
    case StructuredTextLexer::MINUS:
    case StructuredTextLexer::PLUS:
        return Role::Binary; // also a prefix when it follows an operator; see below
    case StructuredTextLexer::REF_TO:
    case StructuredTextLexer::POINTER:
    case StructuredTextLexer::ARRAY:
        return Role::TypePrefix;
    case StructuredTextLexer::OR:
    case StructuredTextLexer::XOR:
    case StructuredTextLexer::AND:
    case StructuredTextLexer::AMPERSAND:
    case StructuredTextLexer::EQUAL:
    case StructuredTextLexer::NOT_EQUAL:
    case StructuredTextLexer::LESS:
    case StructuredTextLexer::GREATER:
    case StructuredTextLexer::LESS_EQUAL:
    case StructuredTextLexer::GREATER_EQUAL:
    case StructuredTextLexer::STAR:
    case StructuredTextLexer::SLASH:
    case StructuredTextLexer::MOD:
    case StructuredTextLexer::POWER:
    case StructuredTextLexer::DOT:
    case StructuredTextLexer::CARET:
        return Role::Binary;
    case StructuredTextLexer::SEMICOLON:
        return Role::EndsStatement;
    default:
        return Role::Other;
    }
}

} // namespace

bool check_nesting(const std::vector<antlr4::Token*>& tokens, FileId file, Diagnostics& diagnostics,
                   const NestingLimits& limits) {
    std::size_t depth = 0;
    std::size_t prefix_run = 0; // consecutive operators: `- - NOT x` nests like parentheses
    std::size_t type_prefixes = 0;
    std::size_t operators = 0;
    const auto fail = [&](const antlr4::Token& token, std::string message) {
        diagnostics.error(DiagnosticCode::E0501, token_range(file, token), std::move(message));
        return false;
    };
    for (const antlr4::Token* token : tokens) {
        if (token->getChannel() != antlr4::Token::DEFAULT_CHANNEL) {
            continue;
        }
        const Role role = role_of(token->getType());
        const bool is_operator = role == Role::Prefix || role == Role::Binary;
        prefix_run = is_operator ? prefix_run + 1 : 0;
        switch (role) {
        case Role::Opens:
            ++depth;
            ++operators; // a call or an index is an operator too: `f(1)(2)` nests
            break;
        case Role::Closes:
            depth = depth > 0 ? depth - 1 : 0;
            break;
        case Role::TypePrefix:
            ++type_prefixes;
            break;
        case Role::Binary:
            ++operators;
            break;
        case Role::EndsStatement:
            type_prefixes = 0;
            operators = 0;
            break;
        case Role::Prefix:
        case Role::Other:
            break;
        }
        if (depth > limits.depth) {
            return fail(*token, "nesting is deeper than " + std::to_string(limits.depth) +
                                    " levels; simplify the code");
        }
        if (prefix_run > limits.chain || type_prefixes > limits.chain) {
            return fail(*token, "more than " + std::to_string(limits.chain) +
                                    " operators or type constructors in a row");
        }
        if (operators > limits.operators_per_statement) {
            return fail(*token, "more than " + std::to_string(limits.operators_per_statement) +
                                    " operators in one statement; split it");
        }
    }
    return true;
}

} // namespace eposp::compiler
