#pragma once

#include <Token.h>
#include <cstddef>
#include <vector>

namespace eposp::compiler {

/// Thrown at the first token the hand-written parser cannot take; the generated parser then
/// reports the syntax error.
struct ParseBail {};

/// The parser's view of the token stream: the tokens on the default channel (pragmas, on the
/// hidden channel, are passed over), looked ahead by any distance, ending at EOF.
class TokenCursor {
public:
    explicit TokenCursor(const std::vector<antlr4::Token*>& tokens);

    const antlr4::Token& peek(std::size_t ahead = 0) const {
        return *visible_[position_ + ahead < visible_.size() ? position_ + ahead
                                                              : visible_.size() - 1];
    }
    std::size_t type(std::size_t ahead = 0) const { return peek(ahead).getType(); }
    bool at(std::size_t token_type) const { return type() == token_type; }

    const antlr4::Token& take() {
        last_ = &peek();
        if (position_ + 1 < visible_.size()) {
            ++position_;
        }
        return *last_;
    }
    const antlr4::Token& expect(std::size_t token_type) {
        if (!at(token_type)) {
            throw ParseBail{};
        }
        return take();
    }
    bool accept(std::size_t token_type) {
        if (!at(token_type)) {
            return false;
        }
        take();
        return true;
    }
    /// The last token taken: where the rule being parsed ends.
    const antlr4::Token* last() const { return last_; }

    /// A place to come back to, to read the tokens after it another way.
    struct Mark {
        std::size_t position;
        const antlr4::Token* last;
    };
    Mark mark() const { return {position_, last_}; }
    void reset(Mark mark) {
        position_ = mark.position;
        last_ = mark.last;
    }

    /// How many tokens ahead the parenthesis or bracket opened `ahead` tokens ahead closes, or
    /// 0 when it never does.
    std::size_t closing(std::size_t ahead) const;

private:
    std::vector<const antlr4::Token*> visible_;
    std::size_t position_ = 0;
    const antlr4::Token* last_ = nullptr;
};

} // namespace eposp::compiler
