#pragma once

#include "eposp/compiler/ast/statements.hpp"

#include <optional>

namespace eposp::compiler::lower {

/// `IF c THEN x := a; ELSE x := b; END_IF` (or without ELSE) where c, a and b are cheap and can
/// neither trap nor have an effect: code generation may evaluate all three and choose with a
/// conditional move instead of a branch that mispredicts whenever c is data, as optimizing C
/// compilers do. `target` is a NameExpression; `otherwise` is null without ELSE.
struct SelectForm {
    const ast::Expression* condition = nullptr;
    const ast::Expression* target = nullptr;
    const ast::Expression* chosen = nullptr;
    const ast::Expression* otherwise = nullptr;
};

/// The select form of `node`, judged on its syntax alone: the caller still checks that the
/// target is a plain variable of a scalar type.
std::optional<SelectForm> select_form(const ast::IfStatement& node);

} // namespace eposp::compiler::lower
