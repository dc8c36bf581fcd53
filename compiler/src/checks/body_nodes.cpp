#include "body_nodes.hpp"

#include <type_traits>
#include <variant>

namespace eposp::compiler::checks {

BodyNodes::BodyNodes(const ast::StatementList& body) {
    add(body);
}

void BodyNodes::add(const ast::StatementList& list) {
    for (const ast::Statement& statement : list) {
        add(statement);
    }
}

// The statement, its own expressions, then the statements it holds.
void BodyNodes::add(const ast::Statement& statement) {
    statements_.push_back(&statement);
    const auto part = [&](const ast::ExpressionPtr& expression) {
        if (expression) {
            add(*expression);
        }
    };
    std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::AssignmentStatement>) {
                assignments_.push_back(&statement);
                part(node.target);
                part(node.value);
            } else if constexpr (std::is_same_v<T, ast::CallStatement>) {
                part(node.call);
            } else if constexpr (std::is_same_v<T, ast::IfStatement>) {
                for (const ast::ConditionalBlock& branch : node.branches) {
                    part(branch.condition);
                }
                for (const ast::ConditionalBlock& branch : node.branches) {
                    add(branch.body);
                }
                add(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                part(node.selector);
                for (const ast::CaseBranch& branch : node.branches) {
                    for (const ast::CaseLabel& label : branch.labels) {
                        part(label.low);
                        part(label.high);
                    }
                }
                for (const ast::CaseBranch& branch : node.branches) {
                    add(branch.body);
                }
                add(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::ForStatement>) {
                part(node.from);
                part(node.to);
                part(node.by);
                add(node.body);
            } else if constexpr (std::is_same_v<T, ast::WhileStatement>) {
                part(node.condition);
                add(node.body);
            } else if constexpr (std::is_same_v<T, ast::RepeatStatement>) {
                part(node.until);
                add(node.body);
            }
        },
        statement.node);
}

void BodyNodes::add(const ast::Expression& expression) {
    expressions_.push_back(&expression);
    std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::NameExpression>) {
                names_.push_back(&expression);
            } else if constexpr (std::is_same_v<T, ast::MemberExpression> ||
                                 std::is_same_v<T, ast::BitAccessExpression>) {
                add(*node.object);
            } else if constexpr (std::is_same_v<T, ast::IndexExpression>) {
                add(*node.array);
                for (const ast::ExpressionPtr& index : node.indices) {
                    add(*index);
                }
            } else if constexpr (std::is_same_v<T, ast::DereferenceExpression>) {
                add(*node.reference);
            } else if constexpr (std::is_same_v<T, ast::ReferenceExpression>) {
                add(*node.target);
            } else if constexpr (std::is_same_v<T, ast::CallExpression>) {
                calls_.push_back(&expression);
                add(*node.callee);
                for (const ast::Argument& argument : node.arguments) {
                    if (argument.value) {
                        add(*argument.value);
                    }
                }
            } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                add(*node.operand);
            } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                add(*node.left);
                add(*node.right);
            }
        },
        expression.node);
}

} // namespace eposp::compiler::checks
