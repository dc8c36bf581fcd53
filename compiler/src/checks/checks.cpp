#include "checks.hpp"

#include "pou_checks.hpp"

namespace eposp::compiler::checks {

void check_program(types::TypedProgram& program, std::span<const ast::CompilationUnit> units,
                   std::size_t linked, const CompileOptions& options, Diagnostics& diagnostics) {
    const CallGraph calls(program, units, linked);
    for (const ast::Pou* pou : calls.pous()) {
        const PouUnderCheck check{program, *pou, calls, diagnostics, calls.body(*pou)};
        check_unreachable_statements(check);
        check_written_inputs(check);
        check_unused_variables(check);
        check_assigned_results(check);
        check_constant_indices(check);
        check_loop_exits(check);
        check_for_loops(check);
        check_overlapping_case_labels(check);
        check_zero_divisors(check);
        check_generic_parameters(check);
        check_whole_assignments(check);
        check_conformant_sizes(check);
        check_writable_targets(check);
        check_call_forms(check);
        check_in_out_connections(check);
        check_repeated_parameters(check);
    }
    const ProgramUnderCheck program_check{program, calls, diagnostics};
    check_constant_subranges(program_check);
    check_string_cuts(program_check);
    check_recursion(calls, diagnostics);
    check_tasks(program, units, options, diagnostics);
    check_program_connections(program, units, diagnostics);
    check_writable_access_paths(program, units, diagnostics);
    check_initial_value_counts(program_check, units);
    check_located_variables(program_check, units);
    check_program_instances(program_check, units);
    check_native_interfaces(program_check, units.last(linked));
    check_runnable_programs(program, units, diagnostics);
}

bool ProgramUnderCheck::includes(const ast::Pou* pou) const {
    return pou == nullptr || calls.runs(*pou);
}

} // namespace eposp::compiler::checks
