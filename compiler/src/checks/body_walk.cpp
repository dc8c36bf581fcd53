#include "body_walk.hpp"

#include <type_traits>
#include <variant>

namespace eposp::compiler::checks {
namespace {

void lists_of(const ast::Statement& statement,
              const std::function<void(const ast::StatementList&)>& visit) {
    std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::IfStatement>) {
                for (const ast::ConditionalBlock& branch : node.branches) {
                    visit(branch.body);
                }
                visit(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                for (const ast::CaseBranch& branch : node.branches) {
                    visit(branch.body);
                }
                visit(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::ForStatement> ||
                                 std::is_same_v<T, ast::WhileStatement> ||
                                 std::is_same_v<T, ast::RepeatStatement>) {
                visit(node.body);
            }
        },
        statement.node);
}

void walk(const ast::Expression& expression,
          const std::function<void(const ast::Expression&)>& visit) {
    visit(expression);
    std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::MemberExpression> ||
                          std::is_same_v<T, ast::BitAccessExpression>) {
                walk(*node.object, visit);
            } else if constexpr (std::is_same_v<T, ast::IndexExpression>) {
                walk(*node.array, visit);
                for (const ast::ExpressionPtr& index : node.indices) {
                    walk(*index, visit);
                }
            } else if constexpr (std::is_same_v<T, ast::DereferenceExpression>) {
                walk(*node.reference, visit);
            } else if constexpr (std::is_same_v<T, ast::ReferenceExpression>) {
                walk(*node.target, visit);
            } else if constexpr (std::is_same_v<T, ast::CallExpression>) {
                walk(*node.callee, visit);
                for (const ast::Argument& argument : node.arguments) {
                    if (argument.value) {
                        walk(*argument.value, visit);
                    }
                }
            } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                walk(*node.operand, visit);
            } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                walk(*node.left, visit);
                walk(*node.right, visit);
            }
        },
        expression.node);
}

void walk_statement(const ast::Statement& statement,
                    const std::function<void(const ast::Expression&)>& visit) {
    const auto part = [&](const ast::ExpressionPtr& expression) {
        if (expression) {
            walk(*expression, visit);
        }
    };
    std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::AssignmentStatement>) {
                part(node.target);
                part(node.value);
            } else if constexpr (std::is_same_v<T, ast::CallStatement>) {
                part(node.call);
            } else if constexpr (std::is_same_v<T, ast::IfStatement>) {
                for (const ast::ConditionalBlock& branch : node.branches) {
                    part(branch.condition);
                }
            } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                part(node.selector);
                for (const ast::CaseBranch& branch : node.branches) {
                    for (const ast::CaseLabel& label : branch.labels) {
                        part(label.low);
                        part(label.high);
                    }
                }
            } else if constexpr (std::is_same_v<T, ast::ForStatement>) {
                part(node.from);
                part(node.to);
                part(node.by);
            } else if constexpr (std::is_same_v<T, ast::WhileStatement>) {
                part(node.condition);
            } else if constexpr (std::is_same_v<T, ast::RepeatStatement>) {
                part(node.until);
            }
        },
        statement.node);
}

} // namespace

void for_each_statement(const ast::StatementList& body,
                        const std::function<void(const ast::Statement&)>& visit) {
    for (const ast::Statement& statement : body) {
        visit(statement);
        lists_of(statement,
                 [&](const ast::StatementList& list) { for_each_statement(list, visit); });
    }
}

void for_each_expression(const ast::StatementList& body,
                         const std::function<void(const ast::Expression&)>& visit) {
    for_each_statement(body,
                       [&](const ast::Statement& statement) { walk_statement(statement, visit); });
}

} // namespace eposp::compiler::checks
