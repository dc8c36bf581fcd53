#pragma once

// A POU body's statements and expressions, found in one walk and kept as lists, so that each
// check loops over the nodes it looks at instead of walking the tree again (issue 17: the checks
// walked each body once per rule through std::function callbacks).

#include "eposp/compiler/ast/statements.hpp"

#include <span>
#include <vector>

namespace eposp::compiler::checks {

class BodyNodes {
public:
    explicit BodyNodes(const ast::StatementList& body);

    /// Every statement, nested ones after the one holding them.
    std::span<const ast::Statement* const> statements() const { return statements_; }
    /// The expressions of the statements in that order (targets, values, conditions, CASE
    /// selectors and labels, FOR bounds), each before its parts (operands, indices, call
    /// arguments and callees).
    std::span<const ast::Expression* const> expressions() const { return expressions_; }
    /// Of those, the AssignmentStatements, in the same order.
    std::span<const ast::Statement* const> assignments() const { return assignments_; }
    /// Of those, the CallExpressions, in the same order.
    std::span<const ast::Expression* const> calls() const { return calls_; }
    /// Of those, the NameExpressions, in the same order.
    std::span<const ast::Expression* const> names() const { return names_; }

private:
    void add(const ast::StatementList& list);
    void add(const ast::Statement& statement);
    void add(const ast::Expression& expression);

    std::vector<const ast::Statement*> statements_;
    std::vector<const ast::Expression*> expressions_;
    std::vector<const ast::Statement*> assignments_;
    std::vector<const ast::Expression*> calls_;
    std::vector<const ast::Expression*> names_;
};

} // namespace eposp::compiler::checks
