// Initial values (grammar rules `declarationInitializer`, `initializer`, `arrayInitElement`).
#include "StructuredTextParser.h"
#include "descent_parser.hpp"

namespace eposp::compiler {

namespace {

using P = generated::StructuredTextParser;

// What may follow an array element: the next one, the end of the brackets, or the end of a
// declaration (';', the next type declaration's name, END_TYPE).
bool follows_array_element(std::size_t token) {
    switch (token) {
    case P::COMMA:
    case P::RIGHT_BRACKET:
    case P::SEMICOLON:
    case P::IDENTIFIER:
    case P::ON:
    case P::END_TYPE:
        return true;
    default:
        return false;
    }
}

} // namespace

// CODESYS V2's `:= 1, 3, 7`: a ',' after the first value, outside brackets, before the end of
// the declaration (';', or ':' and ':=' of the next one after a type without its ';').
ast::InitializerPtr DescentParser::declaration_initializer() {
    const antlr4::Token& start = cursor_.peek();
    std::size_t depth = 0;
    for (std::size_t ahead = 0;; ++ahead) {
        const std::size_t type = cursor_.type(ahead);
        if (type == antlr4::Token::EOF) {
            return initializer();
        }
        if (type == P::LEFT_PAREN || type == P::LEFT_BRACKET) {
            ++depth;
        } else if (depth > 0) {
            depth -= type == P::RIGHT_PAREN || type == P::RIGHT_BRACKET ? 1 : 0;
        } else if (type == P::COMMA) {
            std::vector<ast::ArrayInitElement> elements = array_elements();
            return nodes_.bare_array_initializer(std::move(elements), range_from(start));
        } else if (type == P::SEMICOLON || type == P::COLON || type == P::ASSIGN ||
                   type == P::END_TYPE || type == P::RIGHT_PAREN || type == P::RIGHT_BRACKET) {
            return initializer();
        }
    }
}

ast::InitializerPtr DescentParser::initializer() {
    const antlr4::Token& start = cursor_.peek();
    auto result = nodes_.make<ast::Initializer>();
    if (cursor_.accept(P::LEFT_BRACKET)) {
        result->value = array_elements();
        cursor_.expect(P::RIGHT_BRACKET);
    } else if (cursor_.at(P::LEFT_PAREN) && at_identifier(1) && cursor_.type(2) == P::ASSIGN) {
        cursor_.take();
        std::vector<ast::StructInitElement> elements;
        do {
            ast::Identifier name = identifier();
            cursor_.expect(P::ASSIGN);
            elements.push_back({std::move(name), initializer()});
        } while (cursor_.accept(P::COMMA));
        cursor_.expect(P::RIGHT_PAREN);
        result->value = std::move(elements);
    } else {
        result->value = expression();
    }
    result->range = range_from(start);
    return result;
}

std::vector<ast::ArrayInitElement> DescentParser::array_elements() {
    std::vector<ast::ArrayInitElement> elements;
    do {
        elements.push_back(array_element());
    } while (cursor_.accept(P::COMMA));
    return elements;
}

// `3(0)` repeats a value; it also reads as a call of 3, the later alternative, which is taken
// only where the repetition cannot be: a ',' or ':=' inside, or an operator after.
ast::ArrayInitElement DescentParser::array_element() {
    if (cursor_.at(P::INTEGER) && cursor_.type(1) == P::LEFT_PAREN) {
        const std::size_t close = cursor_.closing(1);
        bool repetition = close != 0 && follows_array_element(cursor_.type(close + 1));
        std::size_t depth = 0;
        for (std::size_t ahead = 2; repetition && ahead < close; ++ahead) {
            const std::size_t type = cursor_.type(ahead);
            if (type == P::LEFT_PAREN || type == P::LEFT_BRACKET) {
                ++depth;
            } else if (type == P::RIGHT_PAREN || type == P::RIGHT_BRACKET) {
                --depth;
            } else if (depth == 0 && (type == P::COMMA || type == P::ASSIGN ||
                                      type == P::OUTPUT_ASSIGN)) {
                repetition = false;
            }
        }
        if (repetition) {
            ast::ExpressionPtr count = nodes_.literal(cursor_.take());
            cursor_.take();
            ast::InitializerPtr value = cursor_.at(P::RIGHT_PAREN) ? nullptr : initializer();
            cursor_.expect(P::RIGHT_PAREN);
            return {std::move(count), std::move(value)};
        }
    }
    return {nullptr, initializer()};
}

} // namespace eposp::compiler
