// W0401: a variable declared and never used is likely a leftover or a typo elsewhere.

#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

#include <fmt/format.h>
#include <unordered_set>

namespace eposp::compiler::checks {

void check_unused_variables(const PouUnderCheck& check) {
    const ast::Pou& pou = check.pou;
    // The names the body refers to, as written (compared ignoring case).
    std::unordered_set<std::string_view, sema::NameHash, sema::NameEqual> used;
    for (const ast::Expression* expression : check.body.names()) {
        const auto& name = std::get<ast::NameExpression>(expression->node);
        if (check.program.model().resolved(name.name) != nullptr) {
            used.insert(name.name.name);
        }
    }
    for (const ast::Statement* statement : check.body.statements()) {
        if (const auto* loop = std::get_if<ast::ForStatement>(&statement->node)) {
            used.insert(loop->control_variable.name);
        }
    }
    for (const ast::DeclarationSection& section : pou.sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr || (variables->kind != ast::VarSectionKind::Var &&
                                     variables->kind != ast::VarSectionKind::Temp &&
                                     variables->kind != ast::VarSectionKind::External)) {
            continue;
        }
        // A PROGRAM's variables are visible from outside (watch, configuration access).
        if (pou.kind == ast::PouKind::Program && variables->kind == ast::VarSectionKind::Var) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            for (const ast::Identifier& name : declaration.names) {
                if (!used.contains(name.name)) {
                    check.diagnostics.warning(
                        DiagnosticCode::W0401, name.range,
                        fmt::format("variable '{}' is never used", name.name));
                }
            }
        }
    }
}

} // namespace eposp::compiler::checks
