// E0405: EXIT and CONTINUE act on the innermost FOR, WHILE or REPEAT (IEC 61131-3 ed. 3,
// 7.3.3.4.5); outside every loop there is nothing for them to leave.

#include "pou_checks.hpp"

#include <type_traits>
#include <variant>

namespace eposp::compiler::checks {
namespace {

void check_list(const ast::StatementList& list, bool in_loop, Diagnostics& diagnostics) {
    for (const ast::Statement& statement : list) {
        std::visit(
            [&](const auto& node) {
                using T = std::decay_t<decltype(node)>;
                if constexpr (std::is_same_v<T, ast::ExitStatement> ||
                              std::is_same_v<T, ast::ContinueStatement>) {
                    if (!in_loop) {
                        diagnostics.error(DiagnosticCode::E0405, statement.range,
                                          std::is_same_v<T, ast::ExitStatement>
                                              ? "EXIT outside a loop"
                                              : "CONTINUE outside a loop");
                    }
                } else if constexpr (std::is_same_v<T, ast::IfStatement>) {
                    for (const ast::ConditionalBlock& branch : node.branches) {
                        check_list(branch.body, in_loop, diagnostics);
                    }
                    check_list(node.else_body, in_loop, diagnostics);
                } else if constexpr (std::is_same_v<T, ast::CaseStatement>) {
                    for (const ast::CaseBranch& branch : node.branches) {
                        check_list(branch.body, in_loop, diagnostics);
                    }
                    check_list(node.else_body, in_loop, diagnostics);
                } else if constexpr (std::is_same_v<T, ast::ForStatement> ||
                                     std::is_same_v<T, ast::WhileStatement> ||
                                     std::is_same_v<T, ast::RepeatStatement>) {
                    check_list(node.body, true, diagnostics);
                }
            },
            statement.node);
    }
}

} // namespace

void check_loop_exits(const PouUnderCheck& check) {
    check_list(check.pou.body, false, check.diagnostics);
}

} // namespace eposp::compiler::checks
