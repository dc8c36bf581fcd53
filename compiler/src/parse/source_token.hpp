#pragma once

#include <Token.h>
#include <TokenSource.h>
#include <cstddef>
#include <cstdint>
#include <string>

namespace eposp::compiler {

class Lexer;

/// A token of the hand-written lexer: what `antlr4::CommonToken` holds in 48 bytes instead of
/// 112 (its type, channel, line and column as wide words, an empty text string, and the source
/// as a pair of pointers), for the half million tokens of a large file, which the token stream
/// keeps until the file is parsed. Its text is read from its lexer's input stream when asked
/// for, without the runtime's virtual calls and interval. The lexer numbers the tokens as the
/// stream does; nothing changes a token once made.
class SourceToken final : public antlr4::Token {
public:
    SourceToken(Lexer& source, std::size_t type, std::size_t channel, std::size_t start,
                std::size_t stop, std::size_t line, std::size_t column, std::size_t index)
        : source_(&source), start_(start), stop_(stop), line_(static_cast<std::uint32_t>(line)),
          column_(static_cast<std::uint32_t>(column)), index_(static_cast<std::uint32_t>(index)),
          type_(static_cast<std::uint16_t>(type)), channel_(static_cast<std::uint8_t>(channel)) {}

    std::string getText() const override;
    std::size_t getType() const override {
        return type_ == UINT16_MAX ? antlr4::Token::EOF : type_;
    }
    std::size_t getLine() const override { return line_; }
    std::size_t getCharPositionInLine() const override { return column_; }
    std::size_t getChannel() const override { return channel_; }
    std::size_t getTokenIndex() const override { return index_; }
    std::size_t getStartIndex() const override { return start_; }
    std::size_t getStopIndex() const override { return stop_; }
    antlr4::TokenSource* getTokenSource() const override;
    antlr4::CharStream* getInputStream() const override;
    std::string toString() const override;

private:
    Lexer* source_;
    std::size_t start_;
    std::size_t stop_;
    // A file of more than 4 Gi lines, columns or tokens would not fit in memory once parsed.
    std::uint32_t line_;
    std::uint32_t column_;
    std::uint32_t index_;
    std::uint16_t type_; // EOF, all ones, is kept as all ones
    std::uint8_t channel_;
};

} // namespace eposp::compiler
