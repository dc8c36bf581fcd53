#pragma once

#include "eposp/compiler/ast/direct_address.hpp"
#include "eposp/compiler/ast/identifier.hpp"
#include "eposp/compiler/ast/literals.hpp"
#include "eposp/compiler/ast/node_arena.hpp"

#include <optional>
#include <variant>
#include <vector>

namespace eposp::compiler::ast {

struct Expression;
using ExpressionPtr = NodePtr<Expression>;

/// Operators of IEC 61131-3 ed. 3, table 71.
enum class UnaryOperator { Negate, Plus, Not };
enum class BinaryOperator {
    Power,
    Multiply,
    Divide,
    Modulo,
    Add,
    Subtract,
    Less,
    Greater,
    LessEqual,
    GreaterEqual,
    Equal,
    NotEqual,
    And,
    Xor,
    Or,
};

struct LiteralExpression {
    Literal value;
};

/// A variable, constant, POU, enumeration value or type named on its own.
struct NameExpression {
    Identifier name;
};

/// `%IX0.0` used directly in code.
struct DirectAddressExpression {
    DirectAddress address;
};

/// `object.member`: structure element, FB instance variable (later also method).
struct MemberExpression {
    ExpressionPtr object;
    Identifier member;
};

/// `word.3`: one bit of an ANY_BIT variable.
struct BitAccessExpression {
    ExpressionPtr object;
    std::uint32_t bit = 0;
};

struct IndexExpression {
    ExpressionPtr array;
    std::vector<ExpressionPtr> indices;
};

/// `ref^`.
struct DereferenceExpression {
    ExpressionPtr reference;
};

/// `REF(x)`.
struct ReferenceExpression {
    ExpressionPtr target;
};

/// One argument of a call: `x`, `IN := x`, `Q => y` or `NOT Q => y`.
struct Argument {
    enum class Kind { Positional, Input, Output };
    Kind kind = Kind::Positional;
    std::optional<Identifier> name;
    bool negated = false;
    ExpressionPtr value;
    SourceRange range;
};

/// A function call, or an FB instance invoked as a statement.
struct CallExpression {
    ExpressionPtr callee;
    std::vector<Argument> arguments;
};

struct UnaryExpression {
    UnaryOperator op = UnaryOperator::Negate;
    ExpressionPtr operand;
};

struct BinaryExpression {
    BinaryOperator op = BinaryOperator::Add;
    ExpressionPtr left;
    ExpressionPtr right;
};

struct Expression {
    SourceRange range;
    std::variant<LiteralExpression, NameExpression, DirectAddressExpression, MemberExpression,
                 BitAccessExpression, IndexExpression, DereferenceExpression, ReferenceExpression,
                 CallExpression, UnaryExpression, BinaryExpression>
        node;
};

} // namespace eposp::compiler::ast
