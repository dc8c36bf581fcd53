#pragma once

// What the type table asks of constant integer expressions (array and subrange bounds, string
// lengths, enumeration values), and what the later stages ask through it. The typing stage's
// constant folder (types/constant_folder.hpp) answers: a constant needs its declared type
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

    /// The value of a constant integer expression (ed. 3, 6.4.2) as the program computes it:
    /// literals, enumeration values, CONSTANTs, operators and the pure standard functions on
    /// those. Nothing when it is not constant.
    virtual std::optional<std::int64_t> fold_integer(const ast::Expression& expression) const = 0;
};

} // namespace eposp::compiler::sema
