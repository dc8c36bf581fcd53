#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "resolver_state.hpp"

#include <span>

namespace eposp::compiler::sema {

/// Pass 1: declares every POU, type, enumeration value, variable, configuration global, global
/// variable list, task and program instance, so that pass 2 resolves uses regardless of file
/// and source order.
void collect_declarations(std::span<const ast::CompilationUnit> units, ResolverState& state);

} // namespace eposp::compiler::sema
