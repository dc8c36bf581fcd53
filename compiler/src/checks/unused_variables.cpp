// W0401: a variable declared and never used is likely a leftover or a typo elsewhere.

#include "body_walk.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

#include <fmt/format.h>
#include <unordered_set>

namespace eposp::compiler::checks {

void check_unused_variables(const PouUnderCheck& check) {
    const ast::Pou& pou = check.pou;
    std::unordered_set<std::string> used; // folded names the body refers to
    for_each_expression(pou.body, [&](const ast::Expression& expression) {
        const auto* name = std::get_if<ast::NameExpression>(&expression.node);
        if (name != nullptr && check.program.model().resolved(name->name) != nullptr) {
            used.insert(sema::fold_case(name->name.name));
        }
    });
    for_each_statement(pou.body, [&](const ast::Statement& statement) {
        if (const auto* loop = std::get_if<ast::ForStatement>(&statement.node)) {
            used.insert(sema::fold_case(loop->control_variable.name));
        }
    });
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
                if (!used.contains(sema::fold_case(name.name))) {
                    check.diagnostics.warning(
                        DiagnosticCode::W0401, name.range,
                        fmt::format("variable '{}' is never used", name.name));
                }
            }
        }
    }
}

} // namespace eposp::compiler::checks
