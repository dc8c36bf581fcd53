#include "source_token.hpp"

#include "lexer.hpp"

namespace eposp::compiler {

static_assert(sizeof(SourceToken) == 48);

// As CommonToken::getText: the input's text, "<EOF>" past its end.
std::string SourceToken::getText() const {
    InputStream& input = source_->input();
    const std::size_t size = input.code_points().size();
    if (start_ < size && stop_ < size) {
        return input.text(start_, stop_);
    }
    return "<EOF>";
}

antlr4::TokenSource* SourceToken::getTokenSource() const {
    return source_;
}

antlr4::CharStream* SourceToken::getInputStream() const {
    return &source_->input();
}

std::string SourceToken::toString() const {
    return "[@" + std::to_string(index_) + "," + std::to_string(start_) + ":" +
           std::to_string(stop_) + "='" + getText() + "',<" + std::to_string(getType()) + ">" +
           (channel_ > 0 ? ",channel=" + std::to_string(channel_) : "") + "," +
           std::to_string(line_) + ":" + std::to_string(column_) + "]";
}

} // namespace eposp::compiler
