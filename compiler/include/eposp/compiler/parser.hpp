#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/source_manager.hpp"

namespace eposp::compiler {

/// Parses one ST source file into its AST. Syntax errors, malformed literals and other
/// problems are reported to `diagnostics`, many per run thanks to error recovery. A file with
/// syntax errors yields an empty unit (later phases only see files that parse); malformed
/// literals leave a placeholder value in the tree next to their error. Any byte string is
/// accepted without crashing or hanging.
ast::CompilationUnit parse(const SourceManager& sources, FileId file, Diagnostics& diagnostics);

} // namespace eposp::compiler
