#pragma once

// The typing stage's result as text: the tree of a compilation unit with the type of each
// expression, its value when constant and what each call calls. The typing stage's snapshot
// tests compare it (tests/compiler/types/snapshots/); it is also a way to see how a program was typed.

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <string>

namespace eposp::compiler::types {

/// `(assign (name x):INT (+ (name y):INT (int 1):INT=1):INT)`, one statement a line. A call's
/// note names its target: `->LIMIT(INT)`, `->TON`, `->Scale` (kind, standard name or POU, the
/// overload's operand type).
std::string dump_typed(const TypedProgram& program, const ast::CompilationUnit& unit);

} // namespace eposp::compiler::types
