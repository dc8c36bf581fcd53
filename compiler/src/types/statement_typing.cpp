// Statements typed (ed. 3, 7.3.3): assignments, calls, conditions, CASE selectors and labels,
// FOR bounds.

#include "constant_folder.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"

#include <fmt/format.h>

namespace eposp::compiler::types {

void ExpressionTyper::statements(const ast::StatementList& list) {
    for (const ast::Statement& statement : list) {
        this->statement(statement);
    }
}

void ExpressionTyper::case_label_constant(const ast::CaseLabel& label, const sema::Type& selector) {
    // As code generation folds them: a ULINT or LWORD selector's labels as unsigned numbers.
    const ConstantFolder& constants = program_.constants();
    const bool unsigned64 = sema::scalar_of(selector) == vm::Scalar::U64;
    const auto folds = [&](const ast::ExpressionPtr& bound, bool as_unsigned) {
        return !bound || (as_unsigned ? constants.fold_unsigned(*bound).has_value()
                                      : constants.fold_integer(*bound).has_value());
    };
    if (folds(label.low, unsigned64) && folds(label.high, unsigned64)) {
        return;
    }
    const bool constant = folds(label.low, true) && folds(label.high, true);
    diagnostics_.error(constant ? DiagnosticCode::E0301 : DiagnosticCode::E0313, label.range,
                       constant ? fmt::format("a CASE label must be a value of {}", selector.name)
                                : "a CASE label must be a constant");
}

void ExpressionTyper::statement(const ast::Statement& statement) {
    std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::AssignmentStatement>) {
                const auto* member = std::get_if<ast::MemberExpression>(&node.target->node);
                if (member != nullptr && model_.enum_value(*node.target) != nullptr) {
                    const auto* object = std::get_if<ast::NameExpression>(&member->object->node);
                    diagnostics_.error(DiagnosticCode::E0204, member->object->range,
                                       fmt::format("'{}' is not a variable",
                                                   object != nullptr ? object->name.name : "?"));
                    type(*node.value, nullptr);
                    return;
                }
                if (!is_variable(*node.target) &&
                    !std::holds_alternative<ast::BitAccessExpression>(node.target->node) &&
                    !std::holds_alternative<ast::NameExpression>(node.target->node)) {
                    diagnostics_.error(DiagnosticCode::E0315, node.target->range,
                                       "this expression is not a variable");
                    type(*node.value, nullptr);
                    return;
                }
                if (const sema::Type* target = type(*node.target, nullptr)) {
                    store(*node.value, *target, "a value");
                }
            } else if constexpr (std::is_same_v<T, ast::CallStatement>) {
                statement_call_ = node.call.get();
                type(*node.call, nullptr);
            } else if constexpr (std::is_same_v<T, ast::IfStatement>) {
                for (const ast::ConditionalBlock& branch : node.branches) {
                    condition(*branch.condition);
                    statements(branch.body);
                }
                statements(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                const sema::Type* selector = type(*node.selector, nullptr);
                if (selector != nullptr && selector->kind != sema::TypeKind::Enum &&
                    !sema::is_integer(program_.types().unranged(*selector)) &&
                    !sema::is_bit_string(*selector)) {
                    diagnostics_.error(
                        DiagnosticCode::E0304, node.selector->range,
                        fmt::format("a CASE selector must be an integer or enumeration, not {}",
                                    selector->name));
                    selector = nullptr;
                }
                for (const ast::CaseBranch& branch : node.branches) {
                    for (const ast::CaseLabel& label : branch.labels) {
                        const std::size_t errors = diagnostics_.error_count();
                        for (const ast::ExpressionPtr* bound : {&label.low, &label.high}) {
                            if (*bound && selector != nullptr) {
                                expect(**bound, *selector, "a CASE label");
                            }
                        }
                        if (selector != nullptr && errors == diagnostics_.error_count()) {
                            case_label_constant(label, *selector);
                        }
                    }
                    statements(branch.body);
                }
                statements(node.else_body);
            } else if constexpr (std::is_same_v<T, ast::ForStatement>) {
                const sema::Symbol* symbol = model_.resolved(node.control_variable);
                const sema::Type* control = symbol != nullptr ? variable_type(*symbol) : nullptr;
                if (control != nullptr) {
                    expect(*node.from, *control, "a FOR bound");
                    expect(*node.to, *control, "a FOR bound");
                    if (node.by) {
                        expect(*node.by, *control, "a FOR step");
                    }
                }
                statements(node.body);
            } else if constexpr (std::is_same_v<T, ast::WhileStatement>) {
                condition(*node.condition);
                statements(node.body);
            } else if constexpr (std::is_same_v<T, ast::RepeatStatement>) {
                statements(node.body);
                condition(*node.until);
            }
        },
        statement.node);
}

} // namespace eposp::compiler::types
