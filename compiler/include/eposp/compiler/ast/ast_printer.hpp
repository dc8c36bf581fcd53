#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"

#include <string>

namespace eposp::compiler::ast {

/// An S-expression dump of the tree, for tests and debugging: `(assign (name x) (int 1))`.
std::string to_sexpr(const Expression& expression);
std::string to_sexpr(const Statement& statement);
std::string to_sexpr(const TypeSpec& type);
std::string to_sexpr(const CompilationUnit& unit);

} // namespace eposp::compiler::ast
