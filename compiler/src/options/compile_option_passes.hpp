#pragma once

// CompileOptions applied to the parsed files before name resolution: both only remove or rename
// declarations, so every later stage sees an ordinary program.

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/compile_options.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/source_manager.hpp"

#include <limits>
#include <span>
#include <vector>

namespace eposp::compiler::options {

/// Where an error in an option points: no file, so it renders as a bare `error: ...`.
inline constexpr SourceRange kOptionRange{std::numeric_limits<FileId>::max(), {}, {}};

/// Drops the CONFIGURATIONs of `options.ignored_configurations` from `units`; an id that is not
/// the file of one of `units` is an error.
void ignore_configurations(std::vector<ast::CompilationUnit>& units, const CompileOptions& options,
                           const SourceManager& sources, Diagnostics& diagnostics);

/// Renames every use as a type of each substituted FUNCTION_BLOCK of `units` to its double and
/// removes the substituted POU. `built_in` (the standard FBs in ST) is only looked up: a
/// standard FB may be either side of a substitution.
void substitute_function_blocks(std::vector<ast::CompilationUnit>& units,
                                std::span<const ast::CompilationUnit> built_in,
                                const CompileOptions& options, Diagnostics& diagnostics);

} // namespace eposp::compiler::options
