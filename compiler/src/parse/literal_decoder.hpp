#pragma once

#include "eposp/compiler/ast/literals.hpp"
#include "eposp/core/result.hpp"

#include <string_view>

namespace eposp::compiler {

/// The lexical forms of literal tokens, which the lexer matches loosely.
enum class LiteralForm {
    Integer,      // 1_000
    BasedInteger, // 16#FF
    Real,         // 1.5E-3
    String,       // 'a$N'
    WideString,   // "a$0041"
    Duration,     // T#1h2m, LTIME#5ns
    Date,         // D#2024-01-31
    TimeOfDay,    // TOD#12:00:00.5
    DateAndTime,  // DT#2024-01-31-12:00:00
    Typed,        // INT#16#FF, REAL#1.5, BOOL#TRUE, STRING#'x', Color#Red
};

/// The exact value of a literal token (IEC 61131-3 ed. 3, 6.3), or a message that says what is
/// wrong with it (a digit outside its base, a value out of the range of its type, a day that
/// does not exist...). Names in an EnumValueLiteral come without source ranges.
core::Result<ast::Literal> decode_literal(LiteralForm form, std::string_view text);

} // namespace eposp::compiler
