#include "token_range.hpp"

#include "../utf8.hpp"

#include <string>

namespace eposp::compiler {

namespace {

SourcePosition start_of(const antlr4::Token& token) {
    return {static_cast<std::uint32_t>(token.getLine()),
            static_cast<std::uint32_t>(token.getCharPositionInLine() + 1)};
}

// Tokens never span lines except EOF and hidden comments, which are reported at their start.
// The input stream holds code points, so a token's character indices count columns; only a
// token made up by error recovery has none, and then its text is counted.
SourcePosition end_of(const antlr4::Token& token) {
    const SourcePosition start = start_of(token);
    const std::size_t first = token.getStartIndex();
    const std::size_t last = token.getStopIndex();
    if (first != INVALID_INDEX && last != INVALID_INDEX) {
        return {start.line,
                start.column + static_cast<std::uint32_t>(last > first ? last - first : 0)};
    }
    const std::string text = token.getType() == antlr4::Token::EOF ? "" : token.getText();
    std::uint32_t code_points = 0;
    for (std::size_t i = 0; i < text.size();) {
        utf8::decode(text, i);
        ++code_points;
    }
    return {start.line, start.column + (code_points > 0 ? code_points - 1 : 0)};
}

} // namespace

SourceRange token_range(FileId file, const antlr4::Token& token) {
    return {file, start_of(token), end_of(token)};
}

SourceRange token_range(FileId file, const antlr4::Token& first, const antlr4::Token& last) {
    return {file, start_of(first), end_of(last)};
}

SourceRange range_after(FileId file, const antlr4::Token& token) {
    SourcePosition position = end_of(token);
    ++position.column;
    return {file, position, position};
}

} // namespace eposp::compiler
