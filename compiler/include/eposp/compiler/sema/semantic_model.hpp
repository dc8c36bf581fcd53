#pragma once

#include "eposp/compiler/sema/node_map.hpp"
#include "eposp/compiler/sema/symbol.hpp"

#include <deque>
#include <unordered_map>

namespace eposp::compiler::sema {

/// The result of name resolution over all files of a program: every symbol and scope, and for
/// each identifier in the AST the symbol it denotes. Type checking looks declarations up here
/// instead of searching names again.
class SemanticModel {
public:
    SemanticModel();
    SemanticModel(const SemanticModel&) = delete;
    SemanticModel& operator=(const SemanticModel&) = delete;
    SemanticModel(SemanticModel&&) = default;
    SemanticModel& operator=(SemanticModel&&) = default;

    /// POUs, user types, configuration globals and the standard library.
    const Scope& global() const { return *global_; }
    /// What an identifier of the AST (a name, member, type name, enum value, formal argument,
    /// FOR variable…) refers to; null when it did not resolve (an error was reported).
    const Symbol* resolved(const ast::Identifier& identifier) const;
    /// The enumeration value `expression` names (`Red`, `Color#Red` or CODESYS's `Color.Red`);
    /// null for any other expression.
    const Symbol* enum_value(const ast::Expression& expression) const;
    /// The members of an inline or declared STRUCT.
    const Scope* struct_members(const ast::TypeSpec& type) const;

    // Construction, used by the resolver.
    Scope& global_scope() { return *global_; }
    const Symbol& add(Symbol symbol);
    Scope& add_scope(const Scope* parent);
    void bind(const ast::Identifier& identifier, const Symbol& symbol);
    void set_struct_members(const ast::TypeSpec& type, const Scope& members);

private:
    std::deque<Symbol> symbols_; // deques: symbols and scopes never move once added
    std::deque<Scope> scopes_;
    Scope* global_;
    NodeMap<ast::Identifier, Symbol> references_;
    std::unordered_map<const ast::TypeSpec*, const Scope*> struct_scopes_;
};

} // namespace eposp::compiler::sema
