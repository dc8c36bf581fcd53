#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/sema/name_map.hpp"
#include "eposp/compiler/source_location.hpp"

#include <string>
#include <string_view>

namespace eposp::compiler::sema {

class Scope;

enum class SymbolKind {
    Variable,
    Pou,
    Type,
    EnumValue,
    Task,
    ProgramInstance,
    Configuration,
    StandardFunction,
    StandardFunctionBlock,
};

/// Something a name can denote. Symbols point back into the AST (which outlives them) so that
/// type checking finds the declaration behind every resolved identifier.
struct Symbol {
    SymbolKind kind = SymbolKind::Variable;
    std::string name{};     // as first written
    SourceRange declared{}; // empty for the standard library
    /// Variable: the VAR section declaring it. The pointers below lead to the declaring AST
    /// node, the one that matches `kind`.
    ast::VarSectionKind section = ast::VarSectionKind::Var;
    const ast::VariableDeclaration* variable = nullptr;
    const ast::Pou* pou = nullptr;
    const ast::TypeDeclaration* type = nullptr;
    const ast::EnumValue* enum_value = nullptr;
    const ast::TaskDeclaration* task = nullptr;
    const ast::ProgramInstance* program_instance = nullptr;
    /// Standard library parameters have no AST: their type is named here.
    std::string_view standard_type{};
    /// Enum value: the enumeration type it belongs to.
    const Symbol* owner = nullptr;
    /// POU, FB type, struct or enumeration: the names declared inside it.
    const Scope* members = nullptr;
};

/// Names declared in one region (IEC identifiers are case-insensitive). A scope looks outward
/// through `parent`; a FUNCTION_BLOCK that EXTENDS another looks through `base` first, so that
/// methods and properties (ed. 3, 6.6.5) later join the same member lookup.
class Scope {
public:
    explicit Scope(const Scope* parent = nullptr) : parent_(parent) {}

    /// Adds `symbol`; returns the symbol already declared under that name, if any.
    const Symbol* declare(const Symbol& symbol);
    /// This scope and its base chain (member lookup: `fb.x`).
    const Symbol* find_member(std::string_view name) const;
    /// Members, then the enclosing scopes (a name used in a body).
    const Symbol* find(std::string_view name) const;

    void set_base(const Scope* base) { base_ = base; }
    const Scope* base() const { return base_; }
    const Scope* parent() const { return parent_; }

private:
    const Scope* parent_;
    const Scope* base_ = nullptr;
    NameMap<const Symbol*> symbols_;
};

/// `name` in upper case, for comparing names (IEC identifiers ignore ASCII case); lookups go
/// through `NameMap`, which needs no folded copy.
std::string fold_case(std::string_view name);

} // namespace eposp::compiler::sema
