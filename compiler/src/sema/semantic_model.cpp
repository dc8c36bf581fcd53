#include "eposp/compiler/sema/semantic_model.hpp"

namespace eposp::compiler::sema {

SemanticModel::SemanticModel() : global_(&scopes_.emplace_back()) {}

const Symbol* SemanticModel::resolved(const ast::Identifier& identifier) const {
    return references_.find(&identifier);
}

const Symbol* SemanticModel::enum_value(const ast::Expression& expression) const {
    const ast::Identifier* name = nullptr;
    if (const auto* plain = std::get_if<ast::NameExpression>(&expression.node)) {
        name = &plain->name;
    } else if (const auto* dotted = std::get_if<ast::MemberExpression>(&expression.node)) {
        name = &dotted->member;
    } else if (const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node)) {
        if (const auto* qualified = std::get_if<ast::EnumValueLiteral>(&literal->value)) {
            name = &qualified->value;
        }
    }
    const Symbol* symbol = name != nullptr ? resolved(*name) : nullptr;
    return symbol != nullptr && symbol->kind == SymbolKind::EnumValue ? symbol : nullptr;
}

const Scope* SemanticModel::struct_members(const ast::TypeSpec& type) const {
    const auto it = struct_scopes_.find(&type);
    return it == struct_scopes_.end() ? nullptr : it->second;
}

const Symbol& SemanticModel::add(Symbol symbol) {
    return symbols_.emplace_back(std::move(symbol));
}

Scope& SemanticModel::add_scope(const Scope* parent) {
    return scopes_.emplace_back(parent);
}

void SemanticModel::bind(const ast::Identifier& identifier, const Symbol& symbol) {
    references_.set(&identifier, &symbol);
}

void SemanticModel::set_struct_members(const ast::TypeSpec& type, const Scope& members) {
    struct_scopes_[&type] = &members;
}

} // namespace eposp::compiler::sema
