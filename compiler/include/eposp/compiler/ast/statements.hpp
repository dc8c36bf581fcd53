#pragma once

#include "eposp/compiler/ast/expressions.hpp"
#include "eposp/compiler/ast/identifier.hpp"

#include <optional>
#include <variant>
#include <vector>

namespace eposp::compiler::ast {

// Statements of IEC 61131-3 ed. 3, 7.3.3 (table 72).

struct Statement;
using StatementList = std::vector<Statement>;

struct AssignmentStatement {
    ExpressionPtr target;
    ExpressionPtr value;
};

/// A function or FB call used as a statement; `call` holds a CallExpression.
struct CallStatement {
    ExpressionPtr call;
};

struct ConditionalBlock {
    ExpressionPtr condition;
    StatementList body;
};

/// IF, its ELSIF branches in order, then ELSE.
struct IfStatement {
    std::vector<ConditionalBlock> branches;
    StatementList else_body;
};

/// One CASE label: a value (`high` empty) or a range `low..high`.
struct CaseLabel {
    ExpressionPtr low;
    ExpressionPtr high;
    SourceRange range;
};

struct CaseBranch {
    std::vector<CaseLabel> labels;
    StatementList body;
};

struct CaseStatement {
    ExpressionPtr selector;
    std::vector<CaseBranch> branches;
    StatementList else_body;
};

struct ForStatement {
    Identifier control_variable;
    ExpressionPtr from;
    ExpressionPtr to;
    ExpressionPtr by; // null: step 1
    StatementList body;
};

struct WhileStatement {
    ExpressionPtr condition;
    StatementList body;
};

struct RepeatStatement {
    StatementList body;
    ExpressionPtr until;
};

struct ExitStatement {};
struct ContinueStatement {};
struct ReturnStatement {};
struct EmptyStatement {};

struct Statement {
    SourceRange range;
    std::variant<AssignmentStatement, CallStatement, IfStatement, CaseStatement, ForStatement,
                 WhileStatement, RepeatStatement, ExitStatement, ContinueStatement, ReturnStatement,
                 EmptyStatement>
        node;
};

} // namespace eposp::compiler::ast
