#include "checks.hpp"

#include "pou_checks.hpp"

namespace eposp::compiler::checks {

void check_program(types::TypedProgram& program, std::span<const ast::CompilationUnit> units,
                   std::size_t linked, Diagnostics& diagnostics) {
    const CallGraph calls(program, units, linked);
    for (const ast::Pou* pou : calls.pous()) {
        const PouUnderCheck check{program, *pou, diagnostics};
        check_unreachable_statements(check);
        check_written_inputs(check);
        check_unused_variables(check);
        check_assigned_results(check);
    }
    check_recursion(calls, diagnostics);
}

} // namespace eposp::compiler::checks
