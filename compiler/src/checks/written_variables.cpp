#include "written_variables.hpp"

#include <type_traits>
#include <variant>

namespace eposp::compiler::checks {
namespace {

class WrittenVariables {
public:
    WrittenNames names;

    void statements(const ast::StatementList& list) {
        for (const ast::Statement& statement : list) {
            std::visit([&](const auto& node) { this->statement(node); }, statement.node);
        }
    }

private:
    void statement(const ast::AssignmentStatement& node) {
        written(*node.target);
        expression(*node.target);
        expression(*node.value);
    }
    void statement(const ast::CallStatement& node) { expression(*node.call); }
    void statement(const ast::IfStatement& node) {
        for (const ast::ConditionalBlock& branch : node.branches) {
            expression(*branch.condition);
            statements(branch.body);
        }
        statements(node.else_body);
    }
    void statement(const ast::CaseStatement& node) {
        expression(*node.selector);
        for (const ast::CaseBranch& branch : node.branches) {
            statements(branch.body);
        }
        statements(node.else_body);
    }
    void statement(const ast::ForStatement& node) {
        names.insert(node.control_variable.name);
        statements(node.body);
    }
    void statement(const ast::WhileStatement& node) { statements(node.body); }
    void statement(const ast::RepeatStatement& node) { statements(node.body); }
    template <typename Other>
    void statement(const Other&) {} // EXIT, CONTINUE, RETURN, ';'

    // Calls can stand anywhere in an expression; their arguments are where writes hide.
    void expression(const ast::Expression& node) {
        std::visit(
            [&](const auto& part) {
                using T = std::decay_t<decltype(part)>;
                if constexpr (std::is_same_v<T, ast::CallExpression>) {
                    for (const ast::Argument& argument : part.arguments) {
                        written(*argument.value); // `=> x`, or a VAR_IN_OUT
                        expression(*argument.value);
                    }
                } else if constexpr (std::is_same_v<T, ast::ReferenceExpression>) {
                    written(*part.target);
                } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                    expression(*part.operand);
                } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                    expression(*part.left);
                    expression(*part.right);
                } else if constexpr (std::is_same_v<T, ast::IndexExpression>) {
                    for (const auto& index : part.indices) {
                        expression(*index);
                    }
                }
            },
            node.node);
    }

    void written(const ast::Expression& target) {
        if (const auto* name = root_variable(target)) {
            names.insert(name->name.name);
        }
    }
};

} // namespace

const ast::NameExpression* root_variable(const ast::Expression& target) {
    const ast::Expression* root = &target;
    for (;;) {
        if (const auto* member = std::get_if<ast::MemberExpression>(&root->node)) {
            root = member->object.get();
        } else if (const auto* element = std::get_if<ast::IndexExpression>(&root->node)) {
            root = element->array.get();
        } else if (const auto* bit = std::get_if<ast::BitAccessExpression>(&root->node)) {
            root = bit->object.get();
        } else {
            return std::get_if<ast::NameExpression>(&root->node);
        }
    }
}

WrittenNames written_variables(const ast::StatementList& body) {
    WrittenVariables walker;
    walker.statements(body);
    return std::move(walker.names);
}

} // namespace eposp::compiler::checks
