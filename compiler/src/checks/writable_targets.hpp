#pragma once

#include "eposp/compiler/ast/expressions.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <optional>

namespace eposp::compiler::checks {

/// Why `target` cannot be written (E0401), as a note on what forbids it: a CONSTANT (a local,
/// a global, a VAR_EXTERNAL CONSTANT, a program's reached by its name), an output of another
/// instance, a direct input address; nullopt when it can be. Program connections ask it too.
std::optional<DiagnosticNote> unwritable(types::TypedProgram& program,
                                         const ast::Expression& target);

} // namespace eposp::compiler::checks
