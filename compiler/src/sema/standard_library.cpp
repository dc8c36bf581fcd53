#include "eposp/compiler/sema/standard_library.hpp"

#include "eposp/compiler/ast/elementary_type.hpp"
#include "eposp/vm/stdlib/manifest.hpp"

#include <string>

namespace eposp::compiler::sema {
namespace {

bool is_elementary_name(std::string_view name) {
    return ast::elementary_type_from_name(name).has_value();
}

/// Declares the FB `variant` with its parameters.
void declare_block(SemanticModel& model, const vm::stdlib::StandardBlockVariant& variant) {
    Scope& members = model.add_scope(nullptr);
    for (const vm::stdlib::StandardParameter& parameter : variant.block->parameters) {
        if (parameter.name.empty()) {
            break;
        }
        members.declare(model.add(Symbol{.kind = SymbolKind::Variable,
                                         .name = std::string(parameter.name),
                                         .section = parameter.output ? ast::VarSectionKind::Output
                                                                     : ast::VarSectionKind::Input,
                                         .standard_type = variant.type_of(parameter)}));
    }
    model.global_scope().declare(model.add(Symbol{
        .kind = SymbolKind::StandardFunctionBlock, .name = variant.name, .members = &members}));
}

} // namespace

void declare_standard_library(SemanticModel& model, bool function_blocks) {
    for (const vm::stdlib::StandardFunction& function : vm::stdlib::standard_functions()) {
        model.global_scope().declare(model.add(
            Symbol{.kind = SymbolKind::StandardFunction, .name = std::string(function.name)}));
    }
    if (!function_blocks) {
        return;
    }
    for (const vm::stdlib::StandardBlockVariant& variant : vm::stdlib::standard_block_variants()) {
        declare_block(model, variant);
    }
}

bool is_conversion_function(std::string_view name) {
    const std::string folded = fold_case(name);
    const std::string_view view = folded;
    if (view.starts_with("TO_")) {
        return is_elementary_name(view.substr(3));
    }
    const auto separator = view.find("_TO_");
    return separator != std::string_view::npos && is_elementary_name(view.substr(0, separator)) &&
           is_elementary_name(view.substr(separator + 4));
}

} // namespace eposp::compiler::sema
