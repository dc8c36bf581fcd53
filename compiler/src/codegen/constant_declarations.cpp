#include "constant_declarations.hpp"

#include <functional>
#include <variant>

namespace eposp::compiler::codegen {

bool is_constant(const ast::Pou& pou, const ast::VariableDeclaration* declaration) {
    for (const ast::DeclarationSection& section : pou.sections) {
        if (const auto* variables = std::get_if<ast::VarSection>(&section)) {
            // Within the section's array: a test per section, not per variable (a POU with
            // many variables would make every call a long search).
            const std::less<const ast::VariableDeclaration*> before;
            const ast::VariableDeclaration* first = variables->variables.data();
            if (!before(declaration, first) &&
                before(declaration, first + variables->variables.size())) {
                return variables->constant;
            }
        }
    }
    return false;
}

} // namespace eposp::compiler::codegen
