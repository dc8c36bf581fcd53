#include "nesting_limit.hpp"

#include "StructuredTextParser.h"
#include "token_range.hpp"

namespace eposp::compiler {

namespace {

using generated::StructuredTextParser;

enum class Role { Other, Opens, Closes, Prefix, TypePrefix, Binary, EndsStatement };

Role role_of(std::size_t type) {
    switch (type) {
    case StructuredTextParser::LEFT_PAREN:
    case StructuredTextParser::LEFT_BRACKET:
    case StructuredTextParser::IF:
    case StructuredTextParser::CASE:
    case StructuredTextParser::FOR:
    case StructuredTextParser::WHILE:
    case StructuredTextParser::REPEAT:
    case StructuredTextParser::STRUCT:
        return Role::Opens;
    case StructuredTextParser::RIGHT_PAREN:
    case StructuredTextParser::RIGHT_BRACKET:
    case StructuredTextParser::END_IF:
    case StructuredTextParser::END_CASE:
    case StructuredTextParser::END_FOR:
    case StructuredTextParser::END_WHILE:
    case StructuredTextParser::END_REPEAT:
    case StructuredTextParser::END_STRUCT:
        return Role::Closes;
    case StructuredTextParser::NOT:
        return Role::Prefix;
    case StructuredTextParser::MINUS:
    case StructuredTextParser::PLUS:
        return Role::Binary; // also a prefix when it follows an operator; see below
    case StructuredTextParser::REF_TO:
    case StructuredTextParser::POINTER:
    case StructuredTextParser::ARRAY:
        return Role::TypePrefix;
    case StructuredTextParser::OR:
    case StructuredTextParser::XOR:
    case StructuredTextParser::AND:
    case StructuredTextParser::AMPERSAND:
    case StructuredTextParser::EQUAL:
    case StructuredTextParser::NOT_EQUAL:
    case StructuredTextParser::LESS:
    case StructuredTextParser::GREATER:
    case StructuredTextParser::LESS_EQUAL:
    case StructuredTextParser::GREATER_EQUAL:
    case StructuredTextParser::STAR:
    case StructuredTextParser::SLASH:
    case StructuredTextParser::MOD:
    case StructuredTextParser::POWER:
    case StructuredTextParser::DOT:
    case StructuredTextParser::CARET:
        return Role::Binary;
    case StructuredTextParser::SEMICOLON:
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
