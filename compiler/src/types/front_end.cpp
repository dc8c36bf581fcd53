#include "eposp/compiler/types/front_end.hpp"

#include "../options/compile_option_passes.hpp"
#include "../stdlib/standard_library_source.hpp"
#include "eposp/compiler/parser.hpp"
#include "eposp/compiler/sema/resolver.hpp"
#include "eposp/compiler/sema/symbol.hpp"

#include <string>

namespace eposp::compiler::types {

const ast::Pou* FrontEnd::library_pou(std::string_view name) const {
    const auto found = library_pous.find(name);
    return found != library_pous.end() ? found->second : nullptr;
}

std::unique_ptr<FrontEnd> resolve_names(SourceManager& sources, std::span<const FileId> files,
                                        Diagnostics& diagnostics, const CompileOptions& options) {
    auto result = std::make_unique<FrontEnd>();
    for (const FileId file : files) {
        result->units.push_back(parse(sources, file, diagnostics));
    }
    // A file with syntax errors yields no declarations: resolving the others against it would
    // only add errors about names that are in fact declared there.
    if (diagnostics.has_errors()) {
        return result;
    }
    // The built-in library is parsed like a user file, so its errors would point into it.
    const FileId library_file =
        sources.add("<standard library>", std::string(stdlib::standard_library_source()));
    result->library_units.push_back(parse(sources, library_file, diagnostics));
    options::ignore_configurations(result->units, options, sources, diagnostics);
    options::substitute_function_blocks(result->units, result->library_units, options, diagnostics);
    if (diagnostics.has_errors()) {
        return result;
    }
    for (const ast::CompilationUnit& unit : result->library_units) {
        for (const ast::Pou& pou : unit.pous) {
            result->library_pous.emplace(pou.name.name, &pou);
        }
    }
    result->model.emplace(sema::resolve(result->units, diagnostics));
    result->library_model.emplace(sema::resolve_library(result->library_units, diagnostics));
    return result;
}

std::unique_ptr<FrontEnd> analyse(SourceManager& sources, std::span<const FileId> files,
                                  Diagnostics& diagnostics, const CompileOptions& options) {
    auto result = resolve_names(sources, files, diagnostics, options);
    if (diagnostics.has_errors()) {
        return result;
    }
    const FrontEnd* front_end = result.get();
    auto program = type_program(
        result->units, *result->model,
        [front_end](std::string_view name) { return front_end->library_pou(name); }, diagnostics);
    if (!diagnostics.has_errors()) {
        type_library(*program, result->library_units, *result->library_model, diagnostics);
    }
    if (!diagnostics.has_errors()) {
        result->program = std::move(program);
    }
    return result;
}

} // namespace eposp::compiler::types
