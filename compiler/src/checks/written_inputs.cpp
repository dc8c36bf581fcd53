// W0405: IEC 61131-3 does not let a POU write its own inputs; CODESYS does and libraries
// written for it (OSCAT) use inputs as scratch variables, so eposp warns instead of refusing.

#include "pou_checks.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {

void check_written_inputs(const PouUnderCheck& check) {
    for (const ast::Statement* statement : check.body.assignments()) {
        const ast::Expression* target =
            std::get<ast::AssignmentStatement>(statement->node).target.get();
        if (const auto* bit = std::get_if<ast::BitAccessExpression>(&target->node)) {
            target = bit->object.get(); // `in.3 := TRUE` writes `in`
        }
        const auto* name = std::get_if<ast::NameExpression>(&target->node);
        const sema::Symbol* symbol =
            name != nullptr ? check.program.model().resolved(name->name) : nullptr;
        // An input declared CONSTANT cannot be written at all (E0401, reported elsewhere).
        if (symbol != nullptr && symbol->kind == sema::SymbolKind::Variable &&
            symbol->section == ast::VarSectionKind::Input && symbol->variable != nullptr &&
            !check.program.is_constant(*symbol->variable)) {
            check.diagnostics.warning(DiagnosticCode::W0405, target->range,
                                      fmt::format("'{}' is an input: IEC 61131-3 does not let a "
                                                  "POU write its inputs (CODESYS does, and so "
                                                  "does eposp)",
                                                  name->name.name));
        }
    }
}

} // namespace eposp::compiler::checks
