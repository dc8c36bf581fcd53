#include "lexer.hpp"

#include "StructuredTextParser.h"
#include "source_token.hpp"

#include <CommonTokenFactory.h>
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace eposp::compiler {

namespace {

using T = generated::StructuredTextParser;

// ANTLR's lexer takes, at each position, the longest text any rule matches, and of rules that
// match the same length the first in the grammar. Each function below returns where the rule
// (or a part of it) named in its comment ends when it matches at `i`, or 0 when it does not.

constexpr char32_t kEnd = 0xFFFFFFFF; // past the text: no character class contains it

char32_t at(std::u32string_view s, std::size_t i) {
    return i < s.size() ? s[i] : kEnd;
}

bool is_digit(char32_t c) {
    return c >= '0' && c <= '9';
}
bool is_letter(char32_t c) {
    return (c | 0x20U) >= 'a' && (c | 0x20U) <= 'z';
}
bool is_name_char(char32_t c) {
    return is_letter(c) || is_digit(c) || c == '_';
} // [0-9a-zA-Z_]
bool is_sign(char32_t c) {
    return c == '+' || c == '-';
}

template <typename Predicate>
std::size_t skip_while(std::u32string_view s, std::size_t i, Predicate in_class) {
    while (in_class(at(s, i))) {
        ++i;
    }
    return i;
}

// fragment DIGITS : [0-9] [0-9_]*
std::size_t digits(std::u32string_view s, std::size_t i) {
    return is_digit(at(s, i))
               ? skip_while(s, i + 1, [](char32_t c) { return is_digit(c) || c == '_'; })
               : 0;
}

// fragment EXPONENT : [eE] [+-]? DIGITS
std::size_t exponent(std::u32string_view s, std::size_t i) {
    if ((at(s, i) | 0x20U) != 'e') {
        return 0;
    }
    return digits(s, is_sign(at(s, i + 1)) ? i + 2 : i + 1);
}

// What follows DIGITS in REAL_LITERAL: '.' DIGITS EXPONENT? | EXPONENT
std::size_t real_tail(std::u32string_view s, std::size_t i) {
    if (at(s, i) == '.') {
        const std::size_t fraction = digits(s, i + 1);
        if (fraction == 0) {
            return 0;
        }
        const std::size_t power = exponent(s, fraction);
        return power != 0 ? power : fraction;
    }
    return exponent(s, i);
}

// What follows DIGITS in BASED_INTEGER: '#' [0-9a-zA-Z_]+
std::size_t based_tail(std::u32string_view s, std::size_t i) {
    return at(s, i) == '#' && is_name_char(at(s, i + 1)) ? skip_while(s, i + 1, is_name_char) : 0;
}

// STRING_LITERAL and WSTRING_LITERAL: quote ('$' . | ~[quote $ \r \n])* quote. Where the text
// ends when the closing quote is missing, that is UNTERMINATED_STRING's end.
struct Quoted {
    bool closed;
    std::size_t end;
};

Quoted quoted(std::u32string_view s, std::size_t i) {
    const char32_t quote = s[i];
    for (++i;;) {
        const char32_t c = at(s, i);
        if (c == quote) {
            return {true, i + 1};
        }
        if (c == '$' && i + 1 < s.size()) {
            i += 2;
        } else if (c == '$' || c == '\r' || c == '\n' || c == kEnd) {
            return {false, i};
        } else {
            ++i;
        }
    }
}

// What follows NAME '#' in TYPED_LITERAL:
// [+-]? DIGITS ('.' DIGITS EXPONENT? | EXPONENT | '#' [0-9a-zA-Z_]+)? | NAME | STRING | WSTRING
std::size_t typed_value(std::u32string_view s, std::size_t i) {
    const char32_t c = at(s, i);
    if (is_sign(c) || is_digit(c)) {
        const std::size_t number = digits(s, is_sign(c) ? i + 1 : i);
        if (number == 0) {
            return 0;
        }
        return std::max({number, real_tail(s, number), based_tail(s, number)});
    }
    if (is_letter(c) || c == '_') {
        return skip_while(s, i + 1, is_name_char);
    }
    if (c == '\'' || c == '"') {
        const Quoted string = quoted(s, i);
        return string.closed ? string.end : 0;
    }
    return 0;
}

// What follows the '#' of the date and time literals: a digit, then characters of `tail`.
template <typename Tail>
std::size_t time_value(std::u32string_view s, std::size_t i, Tail tail) {
    return is_digit(at(s, i)) ? skip_while(s, i + 1, tail) : 0;
}

bool is_one_of(std::string_view word, std::initializer_list<std::string_view> words) {
    return std::find(words.begin(), words.end(), word) != words.end();
}

// The date and time literals and TYPED_LITERAL, at the '#' after the name `word` (upper case):
// the rule that matches the longest text, the first of the grammar on a tie, or nothing.
struct Match {
    std::size_t type;
    std::size_t end;
};

Match literal_after_name(std::u32string_view s, std::string_view word, std::size_t hash) {
    Match best{0, 0};
    const auto consider = [&](std::size_t type, std::size_t end) {
        if (end > best.end) {
            best = {type, end};
        }
    };
    const std::size_t value = hash + 1;
    if (is_one_of(word, {"T", "TIME", "LT", "LTIME"})) {
        consider(T::TIME_LITERAL,
                 time_value(s, is_sign(at(s, value)) ? value + 1 : value,
                            [](char32_t c) { return is_name_char(c) || c == '.'; }));
    }
    if (is_one_of(word, {"D", "DATE", "LD", "LDATE"})) {
        consider(T::DATE_LITERAL, time_value(s, value, [](char32_t c) {
                     return is_digit(c) || c == '_' || c == '-';
                 }));
    }
    if (is_one_of(word, {"TOD", "TIME_OF_DAY", "LTOD", "LTIME_OF_DAY"})) {
        consider(T::TIME_OF_DAY_LITERAL, time_value(s, value, [](char32_t c) {
                     return is_digit(c) || c == ':' || c == '.' || c == '_';
                 }));
    }
    if (is_one_of(word, {"DT", "DATE_AND_TIME", "LDT", "LDATE_AND_TIME"})) {
        consider(T::DATE_AND_TIME_LITERAL, time_value(s, value, [](char32_t c) {
                     return is_digit(c) || c == ':' || c == '.' || c == '_' || c == '-';
                 }));
    }
    consider(T::TYPED_LITERAL, typed_value(s, value));
    return best;
}

struct Keyword {
    std::string_view word;
    std::size_t type;
};

constexpr std::array kKeywords{
    Keyword{"AND", T::AND},
    Keyword{"ARRAY", T::ARRAY},
    Keyword{"AT", T::AT},
    Keyword{"BY", T::BY},
    Keyword{"CASE", T::CASE},
    Keyword{"CONFIGURATION", T::CONFIGURATION},
    Keyword{"CONSTANT", T::CONSTANT},
    Keyword{"CONTINUE", T::CONTINUE},
    Keyword{"DO", T::DO},
    Keyword{"ELSE", T::ELSE},
    Keyword{"ELSIF", T::ELSIF},
    Keyword{"END_CASE", T::END_CASE},
    Keyword{"END_CONFIGURATION", T::END_CONFIGURATION},
    Keyword{"END_FOR", T::END_FOR},
    Keyword{"END_FUNCTION", T::END_FUNCTION},
    Keyword{"END_FUNCTION_BLOCK", T::END_FUNCTION_BLOCK},
    Keyword{"END_IF", T::END_IF},
    Keyword{"END_PROGRAM", T::END_PROGRAM},
    Keyword{"END_REPEAT", T::END_REPEAT},
    Keyword{"END_RESOURCE", T::END_RESOURCE},
    Keyword{"END_STRUCT", T::END_STRUCT},
    Keyword{"END_TYPE", T::END_TYPE},
    Keyword{"END_VAR", T::END_VAR},
    Keyword{"END_WHILE", T::END_WHILE},
    Keyword{"EXIT", T::EXIT},
    Keyword{"EXTENDS", T::EXTENDS},
    Keyword{"FALSE", T::FALSE},
    Keyword{"FOR", T::FOR},
    Keyword{"FUNCTION", T::FUNCTION},
    Keyword{"FUNCTION_BLOCK", T::FUNCTION_BLOCK},
    Keyword{"IF", T::IF},
    Keyword{"IMPLEMENTS", T::IMPLEMENTS},
    Keyword{"MOD", T::MOD},
    Keyword{"NON_RETAIN", T::NON_RETAIN},
    Keyword{"NOT", T::NOT},
    Keyword{"NULL", T::NULL_REFERENCE},
    Keyword{"OF", T::OF},
    Keyword{"ON", T::ON},
    Keyword{"OR", T::OR},
    Keyword{"PERSISTENT", T::PERSISTENT},
    Keyword{"POINTER", T::POINTER},
    Keyword{"PROGRAM", T::PROGRAM},
    Keyword{"READ_ONLY", T::READ_ONLY},
    Keyword{"READ_WRITE", T::READ_WRITE},
    Keyword{"REF", T::REF},
    Keyword{"REF_TO", T::REF_TO},
    Keyword{"REPEAT", T::REPEAT},
    Keyword{"RESOURCE", T::RESOURCE},
    Keyword{"RETAIN", T::RETAIN},
    Keyword{"RETURN", T::RETURN},
    Keyword{"STRUCT", T::STRUCT},
    Keyword{"TASK", T::TASK},
    Keyword{"THEN", T::THEN},
    Keyword{"TO", T::TO},
    Keyword{"TRUE", T::TRUE},
    Keyword{"TYPE", T::TYPE},
    Keyword{"UNTIL", T::UNTIL},
    Keyword{"VAR", T::VAR},
    Keyword{"VAR_ACCESS", T::VAR_ACCESS},
    Keyword{"VAR_EXTERNAL", T::VAR_EXTERNAL},
    Keyword{"VAR_GLOBAL", T::VAR_GLOBAL},
    Keyword{"VAR_INPUT", T::VAR_INPUT},
    Keyword{"VAR_IN_OUT", T::VAR_IN_OUT},
    Keyword{"VAR_OUTPUT", T::VAR_OUTPUT},
    Keyword{"VAR_TEMP", T::VAR_TEMP},
    Keyword{"WHILE", T::WHILE},
    Keyword{"WITH", T::WITH},
    Keyword{"XOR", T::XOR},
};
constexpr std::size_t kLongestKeyword = 18; // END_FUNCTION_BLOCK, longer than any literal prefix

// FNV-1a: a name's few characters mixed in a few instructions each.
constexpr std::uint32_t hash(std::string_view word) {
    std::uint32_t h = 2166136261U;
    for (const char c : word) {
        h = (h ^ static_cast<std::uint8_t>(c)) * 16777619U;
    }
    return h;
}

// The keywords by hash, open addressing with linear probing, kNoKeyword where there is none: a
// name is looked up with one string comparison at most where a binary search made seven.
constexpr std::size_t kKeywordSlots = 256;
constexpr std::uint8_t kNoKeyword = 0xFF;
static_assert(kKeywords.size() < kKeywordSlots / 2 && kKeywords.size() < kNoKeyword);

constexpr std::array<std::uint8_t, kKeywordSlots> make_keyword_slots() {
    std::array<std::uint8_t, kKeywordSlots> slots{};
    slots.fill(kNoKeyword);
    for (std::size_t k = 0; k < kKeywords.size(); ++k) {
        std::size_t slot = hash(kKeywords[k].word) % kKeywordSlots;
        while (slots[slot] != kNoKeyword) {
            slot = (slot + 1) % kKeywordSlots;
        }
        slots[slot] = static_cast<std::uint8_t>(k);
    }
    return slots;
}
constexpr std::array<std::uint8_t, kKeywordSlots> kKeywordSlotsTable = make_keyword_slots();

// The keyword's token type, or IDENTIFIER. `word` is in upper case.
std::size_t keyword_type(std::string_view word) {
    for (std::size_t slot = hash(word) % kKeywordSlots; kKeywordSlotsTable[slot] != kNoKeyword;
         slot = (slot + 1) % kKeywordSlots) {
        const Keyword& keyword = kKeywords[kKeywordSlotsTable[slot]];
        if (keyword.word.size() == word.size() && keyword.word[0] == word[0] &&
            keyword.word == word) {
            return keyword.type;
        }
    }
    return T::IDENTIFIER;
}

// A name, or a keyword (the same length: the keyword rules come first), or a literal that starts
// with a name and a '#' (longer).
Match name_or_literal(std::u32string_view s, std::size_t start) {
    const std::size_t end = skip_while(s, start + 1, is_name_char);
    // A name longer than any keyword is compared as "": no keyword, no prefix of a date or time.
    std::array<char, kLongestKeyword> upper{};
    const std::size_t length = end - start <= kLongestKeyword ? end - start : 0;
    for (std::size_t i = 0; i < length; ++i) {
        const char32_t c = s[start + i];
        upper[i] = static_cast<char>(is_letter(c) ? c & ~0x20U : c);
    }
    const std::string_view word(upper.data(), length);
    if (at(s, end) == '#') {
        const Match literal = literal_after_name(s, word, end);
        if (literal.end != 0) {
            return literal;
        }
    }
    return {keyword_type(word), end};
}

// REAL_LITERAL, BASED_INTEGER or INTEGER.
Match number(std::u32string_view s, std::size_t start) {
    const std::size_t integer = digits(s, start);
    if (const std::size_t real = real_tail(s, integer); real != 0) {
        return {T::REAL_LITERAL, real};
    }
    if (const std::size_t based = based_tail(s, integer); based != 0) {
        return {T::BASED_INTEGER, based};
    }
    return {T::INTEGER, integer};
}

// DIRECT_ADDRESS : '%' [IQMiqm] ([XBWDLxbwdl]? [0-9]+ ('.' [0-9]+)* | '*')
std::size_t direct_address(std::u32string_view s, std::size_t start) {
    const char32_t area = at(s, start + 1) | 0x20U;
    if (area != 'i' && area != 'q' && area != 'm') {
        return 0;
    }
    std::size_t i = start + 2;
    if (at(s, i) == '*') {
        return i + 1;
    }
    const char32_t size = at(s, i) | 0x20U;
    if (size == 'x' || size == 'b' || size == 'w' || size == 'd' || size == 'l') {
        ++i;
    }
    if (!is_digit(at(s, i))) {
        return 0;
    }
    i = skip_while(s, i, is_digit);
    while (at(s, i) == '.' && is_digit(at(s, i + 1))) {
        i = skip_while(s, i + 1, is_digit);
    }
    return i;
}

// BLOCK_COMMENT : '(*' (BLOCK_COMMENT | .)*? '*)' and C_COMMENT : '/*' (C_COMMENT | .)*? '*/',
// from after the opening pair, as the runtime runs such a non-greedy loop: it follows every way
// of reading the text at once, in the order it prefers them (leave the loop at '*', open a
// nested comment, take any character), each at its depth of nesting; when one way closes the
// outermost comment, the ways after it are dropped, those before it go on, and the last close
// found ends the comment. A nested comment left open is thus read as plain text.
std::size_t comment(std::u32string_view s, std::size_t i, char32_t open, char32_t close) {
    enum Step : std::uint8_t { CloseStar, Close, Open, OpenStar, Any, kSteps };
    struct Way {
        Step step;
        std::size_t depth;
    };
    std::vector<Way> ways;
    std::vector<Way> next;
    std::vector<std::size_t> added; // the character at which a way was last added, plus one
    std::size_t character = 0;
    const auto add = [&](Step step, std::size_t depth) {
        const std::size_t key = depth * kSteps + step;
        if (key >= added.size()) {
            added.resize(key + kSteps * 8, 0);
        }
        if (added[key] != character + 1) {
            added[key] = character + 1;
            next.push_back({step, depth});
        }
    };
    const auto loop = [&](std::size_t depth) {
        add(CloseStar, depth);
        add(Open, depth);
        add(Any, depth);
    };
    loop(0);
    std::size_t end = 0;
    for (; i < s.size() && !next.empty(); ++i) {
        ways.swap(next);
        next.clear();
        ++character;
        const char32_t c = s[i];
        for (const Way& way : ways) {
            if (way.step == CloseStar && c == '*') {
                add(Close, way.depth);
            } else if (way.step == Close && c == close) {
                if (way.depth == 0) {
                    end = i + 1;
                    break;
                }
                loop(way.depth - 1);
            } else if (way.step == Open && c == open) {
                add(OpenStar, way.depth);
            } else if (way.step == OpenStar && c == '*') {
                loop(way.depth + 1);
            } else if (way.step == Any) {
                loop(way.depth);
            }
        }
    }
    return end;
}

bool is_whitespace(char32_t c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f';
}

// The token at `start` (not at the end of the text).
Match match(std::u32string_view s, std::size_t start) {
    const char32_t c = s[start];
    const char32_t next = at(s, start + 1);
    const auto one = [&](std::size_t type) {
        return Match{type, start + 1};
    };
    const auto two = [&](std::size_t type) {
        return Match{type, start + 2};
    };
    if (is_letter(c) || c == '_') {
        return name_or_literal(s, start);
    }
    if (is_digit(c)) {
        return number(s, start);
    }
    switch (c) {
    case ' ':
    case '\t':
    case '\r':
    case '\n':
    case '\f':
        return {T::WHITESPACE, skip_while(s, start + 1, is_whitespace)};
    case '(':
        if (next == '*') {
            if (const std::size_t end = comment(s, start + 2, '(', ')'); end != 0) {
                return {T::BLOCK_COMMENT, end};
            }
        }
        return one(T::LEFT_PAREN);
    case '/':
        if (next == '/') {
            return {T::LINE_COMMENT, skip_while(s, start + 2, [](char32_t d) {
                        return d != '\r' && d != '\n' && d != kEnd;
                    })};
        }
        if (next == '*') {
            if (const std::size_t end = comment(s, start + 2, '/', '/'); end != 0) {
                return {T::C_COMMENT, end};
            }
        }
        return one(T::SLASH);
    case '{': {
        const std::size_t close = s.find(U'}', start + 1);
        return close != std::u32string_view::npos ? Match{T::PRAGMA, close + 1}
                                                  : one(T::INVALID_CHARACTER);
    }
    case '\'':
    case '"': {
        const Quoted string = quoted(s, start);
        if (string.closed) {
            return {c == '\'' ? T::STRING_LITERAL : T::WSTRING_LITERAL, string.end};
        }
        return {T::UNTERMINATED_STRING, string.end};
    }
    case '%': {
        const std::size_t end = direct_address(s, start);
        return end != 0 ? Match{T::DIRECT_ADDRESS, end} : one(T::INVALID_CHARACTER);
    }
    case ':':
        return next == '=' ? two(T::ASSIGN) : one(T::COLON);
    case '=':
        return next == '>' ? two(T::OUTPUT_ASSIGN) : one(T::EQUAL);
    case '.':
        return next == '.' ? two(T::RANGE) : one(T::DOT);
    case '*':
        return next == '*' ? two(T::POWER) : one(T::STAR);
    case '<':
        return next == '=' ? two(T::LESS_EQUAL) : next == '>' ? two(T::NOT_EQUAL) : one(T::LESS);
    case '>':
        return next == '=' ? two(T::GREATER_EQUAL) : one(T::GREATER);
    case ';':
        return one(T::SEMICOLON);
    case ',':
        return one(T::COMMA);
    case ')':
        return one(T::RIGHT_PAREN);
    case '[':
        return one(T::LEFT_BRACKET);
    case ']':
        return one(T::RIGHT_BRACKET);
    case '^':
        return one(T::CARET);
    case '&':
        return one(T::AMPERSAND);
    case '+':
        return one(T::PLUS);
    case '-':
        return one(T::MINUS);
    default:
        return one(T::INVALID_CHARACTER);
    }
}

bool is_skipped(std::size_t type) {
    return type == T::WHITESPACE || type == T::BLOCK_COMMENT || type == T::C_COMMENT ||
           type == T::LINE_COMMENT;
}

} // namespace

Lexer::Lexer(InputStream& input) : input_(input), text_(input.code_points()) {}

antlr4::TokenFactory<antlr4::CommonToken>* Lexer::getTokenFactory() {
    return antlr4::CommonTokenFactory::DEFAULT.get();
}

std::unique_ptr<antlr4::Token> Lexer::nextToken() {
    return std::make_unique<SourceToken>(next());
}

std::vector<std::vector<SourceToken>> Lexer::all_tokens() {
    // 96 KiB a block: below the size from which malloc maps memory of its own.
    constexpr std::size_t kTokensABlock = 2048;
    std::vector<std::vector<SourceToken>> blocks;
    for (;;) {
        std::vector<SourceToken>& block = blocks.emplace_back();
        block.reserve(kTokensABlock);
        while (block.size() < kTokensABlock) {
            block.push_back(next());
            if (block.back().getType() == antlr4::Token::EOF) {
                return blocks;
            }
        }
    }
}

SourceToken Lexer::next() {
    for (;;) {
        const std::size_t start = position_;
        if (start >= text_.size()) {
            // Like ANTLR's: empty, stop index one before its start (all ones in an empty file).
            return SourceToken(*this, antlr4::Token::EOF, antlr4::Token::DEFAULT_CHANNEL, start,
                               start - 1, line_, column_, tokens_++);
        }
        const Match token = match(text_, start);
        if (is_skipped(token.type)) {
            advance_to(token.end);
            continue;
        }
        // Pragmas stay on the hidden channel, where the AST builder reads them.
        const std::size_t channel = token.type == T::PRAGMA ? antlr4::Token::HIDDEN_CHANNEL
                                                            : antlr4::Token::DEFAULT_CHANNEL;
        SourceToken result(*this, token.type, channel, start, token.end - 1, line_, column_,
                           tokens_++);
        advance_to(token.end);
        return result;
    }
}

// ANTLR counts a line at each '\n' ("\r\n" too, a lone '\r' not).
void Lexer::advance_to(std::size_t end) {
    for (; position_ < end; ++position_) {
        if (text_[position_] == '\n') {
            ++line_;
            column_ = 0;
        } else {
            ++column_;
        }
    }
}

} // namespace eposp::compiler
