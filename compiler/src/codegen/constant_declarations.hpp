#pragma once

#include "eposp/compiler/ast/declarations.hpp"

namespace eposp::compiler::codegen {

/// Whether `declaration` is in a VAR CONSTANT section of `pou`.
bool is_constant(const ast::Pou& pou, const ast::VariableDeclaration* declaration);

} // namespace eposp::compiler::codegen
