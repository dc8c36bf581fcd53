#pragma once

#include "eposp/compiler/ast/statements.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace eposp::compiler::checks {

/// What the definite-assignment pass needs from type checking.
struct AssignmentFacts {
    /// Whether `call` may write the variable given as its argument `index` as it is (`f(x)`,
    /// `f(IO := x)`): a VAR_IN_OUT, or a parameter that cannot be told.
    std::function<bool(const ast::CallExpression& call, std::size_t index)> may_write;
    /// Whether the labels of a CASE cover every value its selector can hold (all enumerators of
    /// an enumeration, the whole of a subrange), so that no path skips all its branches.
    std::function<bool(const ast::CaseStatement& node)> exhaustive;
};

/// A variable that some path through a body leaves unassigned: the RETURNs it reaches without
/// assigning the variable, and whether such a path falls off the end of the body.
struct UnassignedPaths {
    std::string name; // folded, as given
    std::vector<SourceRange> returns;
    bool at_end = false;
};

/// Definite assignment of `variables` (folded names) over `body`, path by path: a variable is
/// definitely assigned at a point when every path from the start of the body to it assigns
/// the whole variable (`x := ...`, `=> x`, a FOR control variable, a VAR_IN_OUT argument).
/// Returns the variables that a path reaching a RETURN or the end leaves unassigned. A
/// variable written only in part somewhere (`x.a := 1`, `x[i] := 2`, `x.3 := TRUE`, `=> x.a`),
/// whose address is taken (REF, ADR) or which is called as an instance is left out: which of
/// its parts a path assigns is not tracked. So is one the body reads where a path may not have
/// assigned it yet (`Sum := Sum + a[i];` in a loop): the body counts on its initial value.
std::vector<UnassignedPaths> unassigned_paths(const ast::StatementList& body,
                                              const std::vector<std::string>& variables,
                                              const AssignmentFacts& facts);

} // namespace eposp::compiler::checks
