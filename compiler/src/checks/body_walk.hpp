#pragma once

// Walks over a POU body for the checks: every statement (nested ones after the one holding
// them) and every expression (each operand after the expression holding it).

#include "eposp/compiler/ast/statements.hpp"

#include <functional>

namespace eposp::compiler::checks {

void for_each_statement(const ast::StatementList& body,
                        const std::function<void(const ast::Statement&)>& visit);

/// The expressions of `body`'s statements (targets, values, conditions, CASE selectors and
/// labels, FOR bounds) and all their parts (operands, indices, call arguments and callees).
void for_each_expression(const ast::StatementList& body,
                         const std::function<void(const ast::Expression&)>& visit);

} // namespace eposp::compiler::checks
