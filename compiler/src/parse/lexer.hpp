#pragma once

#include "input_stream.hpp"
#include "source_token.hpp"

#include <CommonToken.h>
#include <TokenSource.h>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::compiler {

/// The lexer rules of StructuredText.g4, written by hand: the same token types, channels, texts,
/// character indices, lines and columns as the lexer ANTLR generates from them
/// (tests/compiler/parse/lexer_equivalence_test.cpp holds the two to that), at a fraction of the
/// cost of the 4.9 runtime's, which looks each character's DFA edge up in a hash map under a
/// lock. Its tokens are `SourceToken`s, less than half the size of `CommonToken`s. Like that lexer
/// it never fails: a character no rule takes is an INVALID_CHARACTER token, and the parser reports
/// malformed input.
class Lexer : public antlr4::TokenSource {
public:
    explicit Lexer(InputStream& input);

    std::unique_ptr<antlr4::Token> nextToken() override;
    /// The tokens from here to EOF (included) as values: what the token stream would hold,
    /// without a heap object a token. In blocks of the heap rather than one array of tens of
    /// megabytes, which malloc would map apart and give back to the system when freed, so that
    /// the stages after parsing would fault their memory in afresh (34.8k page faults instead
    /// of 29.4k in `eposp build` of large 70000, at about 2 µs each).
    std::vector<std::vector<SourceToken>> all_tokens();
    InputStream& input() const { return input_; }
    std::size_t getLine() const override { return line_; }
    std::size_t getCharPositionInLine() override { return column_; }
    antlr4::CharStream* getInputStream() override { return &input_; }
    std::string getSourceName() override { return input_.getSourceName(); }
    /// For the tokens the parser's error recovery makes up.
    antlr4::TokenFactory<antlr4::CommonToken>* getTokenFactory() override;

private:
    SourceToken next();
    void advance_to(std::size_t end);

    InputStream& input_;
    std::u32string_view text_;
    std::size_t position_ = 0;
    std::size_t tokens_ = 0; // made so far: the next one's index in the token stream
    std::size_t line_ = 1;   // as ANTLR counts: lines from 1,
    std::size_t column_ = 0; // columns from 0, in code points
};

} // namespace eposp::compiler
