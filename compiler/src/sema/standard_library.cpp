#include "eposp/compiler/sema/standard_library.hpp"

#include "eposp/compiler/ast/elementary_type.hpp"
#include "eposp/vm/stdlib/manifest.hpp"

#include <string>

namespace eposp::compiler::sema {
namespace {

bool is_elementary_name(std::string_view name) {
    return ast::elementary_type_from_name(name).has_value();
}

/// Declares the FB `name` with the parameters of `block`, the counters' INT as `counter_type`.
void declare_block(SemanticModel& model, std::string name,
                   const vm::stdlib::StandardFunctionBlock& block, std::string_view counter_type) {
    Scope& members = model.add_scope(nullptr);
    for (const vm::stdlib::StandardParameter& parameter : block.parameters) {
        if (parameter.name.empty()) {
            break;
        }
        members.declare(model.add(Symbol{
            .kind = SymbolKind::Variable,
            .name = std::string(parameter.name),
            .section = parameter.output ? ast::VarSectionKind::Output : ast::VarSectionKind::Input,
            .standard_type = parameter.type == "INT" ? counter_type : parameter.type}));
    }
    model.global_scope().declare(model.add(Symbol{
        .kind = SymbolKind::StandardFunctionBlock, .name = std::move(name), .members = &members}));
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
    const auto blocks = vm::stdlib::standard_function_blocks();
    for (const vm::stdlib::StandardFunctionBlock& block : blocks) {
        declare_block(model, std::string(block.name), block, "INT");
    }
    // The typed counters of table 45 (CTU_DINT…), after all the others.
    for (const std::string_view type : vm::stdlib::kCounterTypes) {
        for (const vm::stdlib::StandardFunctionBlock& block : blocks) {
            if (block.counter) {
                declare_block(model, std::string(block.name) + "_" + std::string(type), block,
                              type);
            }
        }
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
