#include "token_cursor.hpp"

#include "StructuredTextParser.h"

namespace eposp::compiler {

using P = generated::StructuredTextParser;

TokenCursor::TokenCursor(const std::vector<antlr4::Token*>& tokens) {
    visible_.reserve(tokens.size());
    for (const antlr4::Token* token : tokens) {
        if (token->getChannel() == antlr4::Token::DEFAULT_CHANNEL) {
            visible_.push_back(token);
        }
    }
}

std::size_t TokenCursor::closing(std::size_t ahead) const {
    std::size_t depth = 0;
    for (std::size_t i = position_ + ahead; i < visible_.size(); ++i) {
        switch (visible_[i]->getType()) {
        case P::LEFT_PAREN:
        case P::LEFT_BRACKET:
            ++depth;
            break;
        case P::RIGHT_PAREN:
        case P::RIGHT_BRACKET:
            if (--depth == 0) {
                return i - position_;
            }
            break;
        default:
            break;
        }
    }
    return 0;
}

} // namespace eposp::compiler
