#include "eposp/compiler/sema/resolver.hpp"

#include "declaration_collector.hpp"
#include "eposp/compiler/sema/standard_library.hpp"
#include "name_resolver.hpp"

namespace eposp::compiler::sema {

namespace {

SemanticModel resolve_with(std::span<const ast::CompilationUnit> units, Diagnostics& diagnostics,
                           bool standard_function_blocks) {
    SemanticModel model;
    declare_standard_library(model, standard_function_blocks);
    ResolverState state{.model = model, .diagnostics = diagnostics};
    collect_declarations(units, state);
    resolve_names(units, state);
    return model;
}

} // namespace

SemanticModel resolve(std::span<const ast::CompilationUnit> units, Diagnostics& diagnostics) {
    return resolve_with(units, diagnostics, true);
}

SemanticModel resolve_library(std::span<const ast::CompilationUnit> units,
                              Diagnostics& diagnostics) {
    return resolve_with(units, diagnostics, false);
}

} // namespace eposp::compiler::sema
