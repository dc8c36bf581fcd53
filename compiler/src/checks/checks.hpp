#pragma once

// The checking stage (issue 17): the language rules that are neither names nor types, run on
// the typed program after typing and before code generation. It reports and changes nothing;
// each rule is one file of this folder (docs/architecture.md, "Compiler").

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/compile_options.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <cstddef>
#include <span>

namespace eposp::compiler::checks {

/// Checks the POUs whose code runs: every POU of the program's own files (all of `units` but
/// the last `linked`) and the POUs with statements of the linked libraries (the last `linked`)
/// that those call, directly or not; a library POU nothing calls is not generated either.
/// `options` are the compilation's (the events the host releases tasks on).
void check_program(types::TypedProgram& program, std::span<const ast::CompilationUnit> units,
                   std::size_t linked, const CompileOptions& options, Diagnostics& diagnostics);

} // namespace eposp::compiler::checks
