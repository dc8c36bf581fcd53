#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"

#include <functional>
#include <string>

namespace eposp::compiler::ast {

/// An S-expression dump of the tree, for tests and debugging: `(assign (name x) (int 1))`.
std::string to_sexpr(const Expression& expression);
std::string to_sexpr(const Statement& statement);
std::string to_sexpr(const TypeSpec& type);
std::string to_sexpr(const CompilationUnit& unit);

/// How a compilation unit's dump is laid out for reading by eye (the typing stage's snapshots):
/// each statement on a line of its own, indented by its nesting, and after each expression what
/// `note` says of it (`(name x):INT`).
struct DumpLayout {
    std::function<std::string(const Expression&)> note{};
};
std::string to_sexpr(const CompilationUnit& unit, const DumpLayout& layout);

} // namespace eposp::compiler::ast
