#pragma once

// The checks of the checking stage, one file each (checks.hpp runs them).

#include "call_graph.hpp"
#include "eposp/compiler/compile_options.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/types/typed_program.hpp"

namespace eposp::compiler::checks {

/// One POU under check, with the typed program it belongs to and its body's nodes.
struct PouUnderCheck {
    types::TypedProgram& program;
    const ast::Pou& pou;
    const CallGraph& calls;
    Diagnostics& diagnostics;
    const BodyNodes& body;
};

/// The program under check: which POUs' values the program-wide checks look at.
struct ProgramUnderCheck {
    types::TypedProgram& program;
    const CallGraph& calls;
    Diagnostics& diagnostics;

    /// Whether values in `pou` are checked: outside POUs (null) always, else when its code runs.
    bool includes(const ast::Pou* pou) const;
};

/// W0401: a variable of a function or FB (a program's VAR_TEMP and VAR_EXTERNAL) never used.
void check_unused_variables(const PouUnderCheck& check);
/// W0402, W0403: an output or a function's result never assigned, or not on every path
/// (definite_assignment.hpp).
void check_assigned_results(const PouUnderCheck& check);
/// W0404: a statement after RETURN, EXIT or CONTINUE in the same list.
void check_unreachable_statements(const PouUnderCheck& check);
/// W0405: an assignment to the POU's own input.
void check_written_inputs(const PouUnderCheck& check);
/// E0402, E0403, E0404: a FOR loop's control variable that is not a local integer, or assigned
/// in its body; a constant step of 0 or negative on an unsigned control variable.
void check_for_loops(const PouUnderCheck& check);
/// E0405: EXIT or CONTINUE outside a loop.
void check_loop_exits(const PouUnderCheck& check);
/// E0406: CASE labels that share a value.
void check_overlapping_case_labels(const PouUnderCheck& check);
/// E0408: a constant zero divisor.
void check_zero_divisors(const PouUnderCheck& check);
/// E0409: a constant array index outside the array's bounds.
void check_constant_indices(const PouUnderCheck& check);
/// E0412: an assignment to a whole FB instance or ARRAY[*].
void check_whole_assignments(const PouUnderCheck& check);
/// E0417: SIZEOF of an ARRAY[*].
void check_conformant_sizes(const PouUnderCheck& check);
/// E0416: a FUNCTION's parameter of type ANY (only native functions take one).
void check_generic_parameters(const PouUnderCheck& check);
/// E0410: a constant stored into a subrange outside its bounds.
void check_constant_subranges(const ProgramUnderCheck& check);
/// W0406: a string literal longer than the string it is stored into.
void check_string_cuts(const ProgramUnderCheck& check);
/// E0421, E0424: a TASK's PRIORITY, SINGLE or INTERVAL the controller cannot run, an event
/// attribute the host refuses (`options.task_event_check`) or that contradicts the others.
void check_tasks(types::TypedProgram& program, std::span<const ast::CompilationUnit> units,
                 const CompileOptions& options, Diagnostics& diagnostics);
/// E0423: a program connection to what is not a global variable, constant, direct address or
/// another program's output (an input), or a global variable or direct output (an output).
void check_program_connections(types::TypedProgram& program,
                               std::span<const ast::CompilationUnit> units,
                               Diagnostics& diagnostics);
/// E0401: an assignment to (or ENO => binding of) what the POU cannot write: a constant, an
/// output of another instance, a direct input address (writable_targets.hpp).
void check_writable_targets(const PouUnderCheck& check);
/// E0401: a READ_WRITE access path to a constant or a direct input address.
void check_writable_access_paths(types::TypedProgram& program,
                                 std::span<const ast::CompilationUnit> units,
                                 Diagnostics& diagnostics);
/// E0413: a call that leaves a VAR_IN_OUT (or a native function's ANY input) unconnected.
void check_in_out_connections(const PouUnderCheck& check);
/// E0414: a call that gives a parameter twice.
void check_repeated_parameters(const PouUnderCheck& check);
/// E0415: EN and ENO of the wrong form or in a positional call, positional arguments of an FB
/// call, a standard function's call that names some inputs but not all.
void check_call_forms(const PouUnderCheck& check);
/// E0411: more initial values than an array has elements.
void check_initial_value_counts(const ProgramUnderCheck& check,
                                std::span<const ast::CompilationUnit> units);
/// E0419: a native function's interface (of `linked`, the linked libraries' files) or a called
/// native block's that the native ABI cannot pass (native_interfaces.hpp).
void check_native_interfaces(const ProgramUnderCheck& check,
                             std::span<const ast::CompilationUnit> linked);
/// E0420: a located variable or a direct address in code that does not fit its address.
void check_located_variables(const ProgramUnderCheck& check,
                             std::span<const ast::CompilationUnit> units);
/// E0422: a PROGRAM used by its name that the configuration gives several instances, or whose
/// name an instance of another type has.
void check_program_instances(const ProgramUnderCheck& check,
                             std::span<const ast::CompilationUnit> units);
/// W0407: no task in the image (no PROGRAM, or a configuration without TASK or instance).
void check_runnable_programs(const types::TypedProgram& program,
                             std::span<const ast::CompilationUnit> units, Diagnostics& diagnostics);
/// E0407: a POU that calls itself, directly or through others (6.6.1.1).
void check_recursion(const CallGraph& calls, Diagnostics& diagnostics);

} // namespace eposp::compiler::checks
