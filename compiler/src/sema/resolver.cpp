#include "eposp/compiler/sema/resolver.hpp"

#include "declaration_collector.hpp"
#include "eposp/compiler/sema/standard_library.hpp"
#include "name_resolver.hpp"

namespace eposp::compiler::sema {

SemanticModel resolve(std::span<const ast::CompilationUnit> units, Diagnostics& diagnostics) {
    SemanticModel model;
    declare_standard_library(model);
    ResolverState state{.model = model, .diagnostics = diagnostics};
    collect_declarations(units, state);
    resolve_names(units, state);
    return model;
}

} // namespace eposp::compiler::sema
