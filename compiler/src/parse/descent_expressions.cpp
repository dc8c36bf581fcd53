// Expressions (grammar rule `expression`, IEC 61131-3 ed. 3, table 71) by precedence climbing,
// which is what ANTLR makes of the left-recursive rule: postfix operators bind tightest, then the
// prefix operators (their operand takes postfix operators only: `-2 ** 2` is 4), then the binary
// operators from `**` down to OR, each level from left to right.
#include "StructuredTextParser.h"
#include "descent_parser.hpp"

namespace eposp::compiler {

namespace {

using P = generated::StructuredTextParser;

// The grammar's order of binary alternatives, highest first; 0 for a token that is none.
int binary_precedence(std::size_t token) {
    switch (token) {
    case P::POWER:
        return 8;
    case P::STAR:
    case P::SLASH:
    case P::MOD:
        return 7;
    case P::PLUS:
    case P::MINUS:
        return 6;
    case P::LESS:
    case P::GREATER:
    case P::LESS_EQUAL:
    case P::GREATER_EQUAL:
        return 5;
    case P::EQUAL:
    case P::NOT_EQUAL:
        return 4;
    case P::AND:
    case P::AMPERSAND:
        return 3;
    case P::XOR:
        return 2;
    case P::OR:
        return 1;
    default:
        return 0;
    }
}

bool is_literal(std::size_t token) {
    switch (token) {
    case P::INTEGER:
    case P::BASED_INTEGER:
    case P::REAL_LITERAL:
    case P::TRUE:
    case P::FALSE:
    case P::NULL_REFERENCE:
    case P::STRING_LITERAL:
    case P::WSTRING_LITERAL:
    case P::UNTERMINATED_STRING:
    case P::TIME_LITERAL:
    case P::DATE_LITERAL:
    case P::TIME_OF_DAY_LITERAL:
    case P::DATE_AND_TIME_LITERAL:
    case P::TYPED_LITERAL:
        return true;
    default:
        return false;
    }
}

} // namespace

bool starts_expression(std::size_t token) {
    switch (token) {
    case P::IDENTIFIER:
    case P::ON:
    case P::LEFT_PAREN:
    case P::REF:
    case P::MOD:
    case P::AND:
    case P::OR:
    case P::XOR:
    case P::DIRECT_ADDRESS:
    case P::MINUS:
    case P::PLUS:
    case P::NOT:
        return true;
    default:
        return is_literal(token);
    }
}

ast::ExpressionPtr DescentParser::expression(int lowest_precedence) {
    ast::ExpressionPtr left = prefixed();
    for (;;) {
        const int precedence = binary_precedence(cursor_.type());
        if (precedence == 0 || precedence < lowest_precedence) {
            return left;
        }
        const std::size_t op = cursor_.take().getType();
        ast::ExpressionPtr right = expression(precedence + 1); // left-associative
        left = nodes_.binary(op, std::move(left), std::move(right));
    }
}

ast::ExpressionPtr DescentParser::prefixed() {
    const std::size_t type = cursor_.type();
    if (type == P::NOT && cursor_.type(1) == P::LEFT_PAREN && at_identifier(2) &&
        cursor_.type(3) == P::ASSIGN) {
        // NOT(IN := x, ENO => e): the formal call of the function NOT (grammar: formalNot).
        const antlr4::Token& callee = cursor_.take();
        cursor_.take();
        std::vector<ast::Argument> inputs;
        do {
            inputs.push_back(argument());
        } while (cursor_.accept(P::COMMA));
        cursor_.expect(P::RIGHT_PAREN);
        return postfixed(nodes_.operator_call(callee, std::move(inputs), range_from(callee)));
    }
    if (type == P::MINUS || type == P::PLUS || type == P::NOT) {
        const antlr4::Token& op = cursor_.take();
        return nodes_.unary(op, prefixed());
    }
    return postfixed(primary());
}

ast::ExpressionPtr DescentParser::primary() {
    const std::size_t type = cursor_.type();
    if (at_identifier()) {
        return nodes_.name(cursor_.take());
    }
    if (is_literal(type)) {
        return nodes_.literal(cursor_.take());
    }
    switch (type) {
    case P::LEFT_PAREN: {
        cursor_.take();
        ast::ExpressionPtr inner = expression();
        cursor_.expect(P::RIGHT_PAREN);
        return inner;
    }
    case P::REF: {
        const antlr4::Token& start = cursor_.take();
        cursor_.expect(P::LEFT_PAREN);
        ast::ExpressionPtr inner = expression();
        cursor_.expect(P::RIGHT_PAREN);
        return nodes_.reference(std::move(inner), range_from(start));
    }
    case P::MOD:
    case P::AND:
    case P::OR:
    case P::XOR: {
        const antlr4::Token& callee = cursor_.take();
        cursor_.expect(P::LEFT_PAREN);
        std::vector<ast::Argument> list = arguments();
        cursor_.expect(P::RIGHT_PAREN);
        return nodes_.operator_call(callee, std::move(list), range_from(callee));
    }
    case P::DIRECT_ADDRESS:
        return nodes_.direct_address_expression(cursor_.take());
    default:
        throw ParseBail{};
    }
}

ast::ExpressionPtr DescentParser::postfixed(ast::ExpressionPtr base) {
    for (;;) {
        switch (cursor_.type()) {
        case P::DOT: {
            const antlr4::Token& dot = cursor_.take();
            if (cursor_.at(P::INTEGER)) {
                base = nodes_.bit_access(std::move(base), dot, cursor_.take());
            } else {
                base = nodes_.member(std::move(base), identifier());
            }
            break;
        }
        case P::LEFT_BRACKET: {
            cursor_.take();
            std::vector<ast::ExpressionPtr> indices;
            do {
                indices.push_back(expression());
            } while (cursor_.accept(P::COMMA));
            base = nodes_.index(std::move(base), std::move(indices),
                                cursor_.expect(P::RIGHT_BRACKET));
            break;
        }
        case P::CARET:
            base = nodes_.dereference(std::move(base), cursor_.take());
            break;
        case P::LEFT_PAREN: {
            cursor_.take();
            std::vector<ast::Argument> list = arguments();
            base = nodes_.call(std::move(base), std::move(list), cursor_.expect(P::RIGHT_PAREN));
            break;
        }
        default:
            return base;
        }
    }
}

// `argumentList?` before a ')'.
std::vector<ast::Argument> DescentParser::arguments() {
    std::vector<ast::Argument> result;
    if (cursor_.at(P::RIGHT_PAREN)) {
        return result;
    }
    do {
        result.push_back(argument());
    } while (cursor_.accept(P::COMMA));
    return result;
}

ast::Argument DescentParser::argument() {
    const antlr4::Token& start = cursor_.peek();
    ast::Argument built;
    if (at_identifier() && cursor_.type(1) == P::ASSIGN) {
        built.kind = ast::Argument::Kind::Input;
        built.name = identifier();
        cursor_.take();
    } else if ((at_identifier() && cursor_.type(1) == P::OUTPUT_ASSIGN) ||
               (cursor_.at(P::NOT) && at_identifier(1) && cursor_.type(2) == P::OUTPUT_ASSIGN)) {
        built.kind = ast::Argument::Kind::Output;
        built.negated = cursor_.accept(P::NOT);
        built.name = identifier();
        cursor_.take();
    }
    built.value = expression();
    built.range = range_from(start);
    return built;
}

void DescentParser::unused_expression() {
    const NodeBuilder::Sink outer = nodes_.sink();
    Diagnostics dropped;
    nodes_.set_sink({&dropped, true});
    expression(); // after a bail the parser is not used again
    nodes_.set_sink(outer);
}

bool DescentParser::at_identifier(std::size_t ahead) const {
    const std::size_t type = cursor_.type(ahead);
    return type == P::IDENTIFIER || type == P::ON;
}

const antlr4::Token& DescentParser::expect_identifier() {
    if (!at_identifier()) {
        throw ParseBail{};
    }
    return cursor_.take();
}

} // namespace eposp::compiler
