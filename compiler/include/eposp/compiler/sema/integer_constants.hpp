#pragma once

// What the type table asks of constant integer expressions (array and subrange bounds, string
// lengths, enumeration values), and what the later stages ask through it. The typing stage's
// constant evaluator (types/constant_evaluator.cpp) answers: a constant needs its declared type
// and a type its constants, so the table, which comes first, names the question here and the
// typing stage that owns both hands it the answer.

#include "eposp/compiler/ast/expressions.hpp"

#include <cstdint>
#include <optional>

namespace eposp::compiler::sema {

struct Type;

class IntegerConstants {
public:
    virtual ~IntegerConstants() = default;

    /// A constant integer expression: literals, enumeration values, CONSTANTs, + - * / MOD,
    /// AND OR XOR and parentheses (ed. 3, 6.4.2), in 64 bits. Nothing when it is not constant.
    virtual std::optional<std::int64_t> fold_integer(const ast::Expression& expression) const = 0;
    /// The same over the values of ULINT and LWORD (CASE labels of such a selector): literals
    /// up to 2^64 - 1, arithmetic modulo 2^64, / and MOD unsigned.
    virtual std::optional<std::uint64_t> fold_unsigned(const ast::Expression& expression) const = 0;
    /// The same as a value of the integer `type` computes at run time (an initial value):
    /// SINT to DINT, USINT, UINT, BYTE and WORD in DINT, UDINT and DWORD modulo 2^32, LINT in
    /// 64 bits, ULINT and LWORD modulo 2^64; the result's bits, sign- or zero-extended. NOT
    /// folds here alone, where the width it flips is known: on literals and constants of `type`.
    virtual std::optional<std::uint64_t> fold_as(const ast::Expression& expression,
                                                 const Type& type) const = 0;
};

} // namespace eposp::compiler::sema
