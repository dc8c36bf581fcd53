// W0404: a statement after RETURN, EXIT or CONTINUE in the same list never runs; reported once
// per list, at the first such statement.

#include "pou_checks.hpp"

#include <variant>

namespace eposp::compiler::checks {
namespace {

void check_list(const ast::StatementList& list, Diagnostics& diagnostics) {
    for (std::size_t i = 0; i + 1 < list.size(); ++i) {
        const auto& node = list[i].node;
        const bool leaves = std::holds_alternative<ast::ReturnStatement>(node) ||
                            std::holds_alternative<ast::ExitStatement>(node) ||
                            std::holds_alternative<ast::ContinueStatement>(node);
        if (leaves && !std::holds_alternative<ast::EmptyStatement>(list[i + 1].node)) {
            diagnostics.warning(DiagnosticCode::W0404, list[i + 1].range,
                                "this statement is never executed");
            return;
        }
    }
}

} // namespace

void check_unreachable_statements(const PouUnderCheck& check) {
    check_list(check.pou.body, check.diagnostics);
    for (const ast::Statement* statement : check.body.statements()) {
        std::visit(
            [&](const auto& node) {
                using T = std::decay_t<decltype(node)>;
                if constexpr (std::is_same_v<T, ast::IfStatement>) {
                    for (const ast::ConditionalBlock& branch : node.branches) {
                        check_list(branch.body, check.diagnostics);
                    }
                    check_list(node.else_body, check.diagnostics);
                } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                    for (const ast::CaseBranch& branch : node.branches) {
                        check_list(branch.body, check.diagnostics);
                    }
                    check_list(node.else_body, check.diagnostics);
                } else if constexpr (std::is_same_v<T, ast::ForStatement> ||
                                     std::is_same_v<T, ast::WhileStatement> ||
                                     std::is_same_v<T, ast::RepeatStatement>) {
                    check_list(node.body, check.diagnostics);
                }
            },
            statement->node);
    }
}

} // namespace eposp::compiler::checks
