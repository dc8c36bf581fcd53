#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/sema/semantic_model.hpp"

#include <span>

namespace eposp::compiler::sema {

/// Name resolution over all files of one program (IEC 61131-3 ed. 3, 6.5.2.2 scope of
/// declarations): builds the global scope (POUs, user types, configuration globals, global
/// variable lists, the standard library) and one scope per POU, then binds every identifier in
/// types, initial values, bodies and configurations to its declaration. Undeclared names,
/// unknown types, duplicate declarations, unmatched VAR_EXTERNALs, unknown tasks and program types
/// and unknown members are reported to `diagnostics`; resolution carries on past them.
SemanticModel resolve(std::span<const ast::CompilationUnit> units, Diagnostics& diagnostics);

/// The same for the built-in library, which declares the standard function blocks itself.
SemanticModel resolve_library(std::span<const ast::CompilationUnit> units,
                              Diagnostics& diagnostics);

} // namespace eposp::compiler::sema
