#pragma once

#include "eposp/compiler/ast/statements.hpp"
#include "eposp/compiler/sema/name_map.hpp"

#include <string_view>
#include <unordered_set>

namespace eposp::compiler::checks {

/// The variable under `x`, `x.a`, `x[i]`, `x.3`: what writing that target changes; null when
/// the target is not rooted in a name (a dereference, a call).
const ast::NameExpression* root_variable(const ast::Expression& target);

/// Names of variables, as the body writes them and compared ignoring case.
using WrittenNames = std::unordered_set<std::string_view, sema::NameHash, sema::NameEqual>;

/// The variables (names of the outermost variable) a body may write: targets of assignments and
/// FOR loops, `=>` bindings, and variables handed to a call as they are or to REF/ADR, which
/// may write through them. An output absent from it is never assigned.
WrittenNames written_variables(const ast::StatementList& body);

} // namespace eposp::compiler::checks
