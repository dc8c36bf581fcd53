// W0407: a program image runs its tasks; files without a PROGRAM (nor a configuration with a
// TASK or a program instance) compile to an image without one, which does nothing. A library
// compiled on its own is such a file set: a warning, not an error.

#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

namespace eposp::compiler::checks {
namespace {

// Whether the image has a task: a configuration's TASK or program instance (one without WITH
// runs in a background task); without a configuration, every PROGRAM runs in a task of its own.
bool has_task(const types::TypedProgram& program, std::span<const ast::CompilationUnit> units) {
    bool configured = false;
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Configuration& configuration : unit.configurations) {
            configured = true;
            for (const ast::Resource& resource : configuration.resources) {
                if (!resource.tasks.empty()) {
                    return true;
                }
                for (const ast::ProgramInstance& instance : resource.programs) {
                    const sema::Symbol* type = program.model().resolved(instance.type);
                    if (type != nullptr && type->kind == sema::SymbolKind::Pou) {
                        return true;
                    }
                }
            }
        }
    }
    if (configured) {
        return false;
    }
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Pou& pou : unit.pous) {
            if (pou.kind == ast::PouKind::Program) {
                return true;
            }
        }
    }
    return false;
}

} // namespace

void check_runnable_programs(const types::TypedProgram& program,
                             std::span<const ast::CompilationUnit> units,
                             Diagnostics& diagnostics) {
    if (!has_task(program, units)) {
        diagnostics.warning(DiagnosticCode::W0407, {},
                            "there is no PROGRAM to run: the image has no task");
    }
}

} // namespace eposp::compiler::checks
