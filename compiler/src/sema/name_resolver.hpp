#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "resolver_state.hpp"

#include <span>

namespace eposp::compiler::sema {

/// Pass 2: binds every identifier used in types, initial values, bodies and configurations to
/// the symbol pass 1 declared for it.
void resolve_names(std::span<const ast::CompilationUnit> units, ResolverState& state);

} // namespace eposp::compiler::sema
