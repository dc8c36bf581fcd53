#include "calls.hpp"

#include "eposp/compiler/sema/symbol.hpp"

namespace eposp::compiler::checks {

Callee callee_of(types::TypedProgram& program, const ast::CallExpression& call) {
    if (const auto* name = std::get_if<ast::NameExpression>(&call.callee->node)) {
        const sema::Symbol* symbol = program.model().resolved(name->name);
        if (symbol != nullptr && symbol->kind == sema::SymbolKind::Pou &&
            symbol->pou->kind == ast::PouKind::Function) {
            return {Callee::Kind::Function, symbol->pou, program.types().frame(*symbol->pou)};
        }
        if (symbol != nullptr && symbol->kind == sema::SymbolKind::StandardFunction) {
            // A standard function the built-in library writes in ST is called like a user one.
            const ast::Pou* pou = program.library_pou(symbol->name);
            if (pou != nullptr && pou->kind == ast::PouKind::Function) {
                return {Callee::Kind::Function, pou, program.types().frame(*pou)};
            }
            return {Callee::Kind::StandardFunction, nullptr, nullptr,
                    sema::fold_case(symbol->name)};
        }
    }
    const sema::Type* instance = program.type_of(*call.callee);
    if (instance != nullptr && instance->kind == sema::TypeKind::Instance) {
        return {Callee::Kind::Instance, instance->pou, instance};
    }
    return {};
}

bool is_enable_argument(const ast::Argument& argument) {
    if (!argument.name) {
        return false;
    }
    return equal_ignoring_case(argument.name->name, "EN") ||
           equal_ignoring_case(argument.name->name, "ENO");
}

} // namespace eposp::compiler::checks
