#include "constant_declarations.hpp"

#include <variant>

namespace eposp::compiler::codegen {

bool is_constant(const ast::Pou& pou, const ast::VariableDeclaration* declaration) {
    for (const ast::DeclarationSection& section : pou.sections) {
        if (const auto* variables = std::get_if<ast::VarSection>(&section)) {
            for (const ast::VariableDeclaration& candidate : variables->variables) {
                if (&candidate == declaration) {
                    return variables->constant;
                }
            }
        }
    }
    return false;
}

} // namespace eposp::compiler::codegen
