#pragma once

// The front end of a compilation without code generation: parse, resolve names, type. Test
// oracles (the reference evaluator) start from here.

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/compile_options.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/sema/name_map.hpp"
#include "eposp/compiler/sema/semantic_model.hpp"
#include "eposp/compiler/source_manager.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace eposp::compiler::types {

/// A program after the front end: its files' trees, the names, the built-in library of
/// standard FBs (stdlib/standard_library_source.cpp) and the types.
struct FrontEnd {
    std::vector<ast::CompilationUnit> units;
    std::optional<sema::SemanticModel> model;
    std::vector<ast::CompilationUnit> library_units;
    std::optional<sema::SemanticModel> library_model;
    std::unique_ptr<TypedProgram> program;

    /// The POU of the built-in library named `name` (a standard FB, a host function); null
    /// when there is none.
    const ast::Pou* library_pou(std::string_view name) const;

    /// library_units' POUs by name, the first of a name (resolve_names fills it once: typing
    /// and the checks ask for every FB instance and call).
    sema::NameMap<const ast::Pou*> library_pous;
};

/// Parses and resolves `files` and the built-in library, without typing: what code generation
/// starts from. Diagnostics tell whether it succeeded. `options` apply to `units` before names
/// are resolved (compile_options.hpp).
std::unique_ptr<FrontEnd> resolve_names(SourceManager& sources, std::span<const FileId> files,
                                        Diagnostics& diagnostics,
                                        const CompileOptions& options = {});

/// resolve_names(), then types the program; null `program` when an error was reported.
std::unique_ptr<FrontEnd> analyse(SourceManager& sources, std::span<const FileId> files,
                                  Diagnostics& diagnostics, const CompileOptions& options = {});

} // namespace eposp::compiler::types
