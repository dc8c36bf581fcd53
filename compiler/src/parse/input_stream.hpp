#pragma once

#include <ANTLRInputStream.h>
#include <string>
#include <string_view>

namespace eposp::compiler {

/// The source text as the parser's tokens point into it: code points, so that a token's start
/// and stop indices count columns.
class InputStream : public antlr4::ANTLRInputStream {
public:
    /// `text` must be valid UTF-8.
    explicit InputStream(const std::string& text);

    /// The code points the lexer reads.
    std::u32string_view code_points() const { return _data; }

    /// The text of the code points `start` to `stop`, both inside the input: ASCII (names,
    /// numbers, keywords: nearly always) copied as it is, anything else converted to UTF-8.
    std::string text(std::size_t start, std::size_t stop);
    std::string getText(const antlr4::misc::Interval& interval) override;
};

} // namespace eposp::compiler
