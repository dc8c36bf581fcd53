#include "eposp/compiler/compiler.hpp"

#include "codegen/program_generator.hpp"
#include "stdlib/standard_library_source.hpp"
#include "eposp/compiler/parser.hpp"
#include "eposp/compiler/sema/resolver.hpp"

#include <string>
#include <vector>

namespace eposp::compiler {

std::optional<vm::Image> compile(SourceManager& sources, std::span<const FileId> files,
                                 Diagnostics& diagnostics) {
    std::vector<ast::CompilationUnit> units;
    for (const FileId file : files) {
        units.push_back(parse(sources, file, diagnostics));
    }
    // A file with syntax errors yields no declarations: resolving the others against it would
    // only add errors about names that are in fact declared there.
    if (diagnostics.has_errors()) {
        return std::nullopt;
    }
    const sema::SemanticModel model = sema::resolve(units, diagnostics);

    // The built-in library is parsed like a user file, so its errors would point into it.
    const FileId library_file =
        sources.add("<standard library>", std::string(stdlib::standard_library_source()));
    std::vector<ast::CompilationUnit> library_units;
    library_units.push_back(parse(sources, library_file, diagnostics));
    const sema::SemanticModel library_model = sema::resolve_library(library_units, diagnostics);
    if (diagnostics.has_errors()) {
        return std::nullopt;
    }
    codegen::ProgramGenerator generator({model, units}, {library_model, library_units},
                                        diagnostics);
    return generator.generate();
}

} // namespace eposp::compiler
