#include "declaration_collector.hpp"

#include <fmt/format.h>

namespace eposp::compiler::sema {

void ResolverState::declare(Scope& scope, const Symbol& symbol) {
    const Symbol* first = scope.declare(symbol);
    if (first == nullptr) {
        return;
    }
    Diagnostic diagnostic(DiagnosticCode::E0202, symbol.declared,
                          fmt::format("'{}' is already declared in this scope", symbol.name));
    if (first->declared.begin.line == 0) {
        diagnostic.message =
            fmt::format("'{}' is already declared by the standard library", symbol.name);
    } else {
        diagnostic.notes.push_back(
            {first->declared, fmt::format("'{}' was first declared here", first->name)});
    }
    diagnostics.report(std::move(diagnostic));
}

namespace {

class DeclarationCollector {
public:
    explicit DeclarationCollector(ResolverState& state) : state_(state), model_(state.model) {}

    void collect(const ast::CompilationUnit& unit) {
        for (const ast::TypeDeclaration& type : unit.types) {
            collect_type_declaration(type);
        }
        for (const ast::Pou& pou : unit.pous) {
            collect_pou(pou);
        }
        for (const ast::Configuration& configuration : unit.configurations) {
            collect_configuration(configuration);
        }
        // A global variable list's names join the global scope, which every POU's scope
        // looks through: they are visible without VAR_EXTERNAL, as in CODESYS.
        collect_sections(model_.global_scope(), unit.global_variable_lists);
    }

private:
    void collect_type_declaration(const ast::TypeDeclaration& declaration) {
        Scope* members = nullptr;
        if (std::holds_alternative<ast::EnumType>(declaration.type.node) ||
            std::holds_alternative<ast::StructType>(declaration.type.node)) {
            members = &model_.add_scope(nullptr);
        }
        const Symbol& symbol = model_.add({.kind = SymbolKind::Type,
                                           .name = declaration.name.name,
                                           .declared = declaration.name.range,
                                           .type = &declaration,
                                           .members = members});
        state_.declare(model_.global_scope(), symbol);
        collect_type_spec(declaration.type, &symbol, members);
    }

    /// Declares the members of STRUCTs and enumerations, including those written inline.
    /// `owner` and `members` are the named type being declared, if any.
    void collect_type_spec(const ast::TypeSpec& spec, const Symbol* owner, Scope* members) {
        if (const auto* enumeration = std::get_if<ast::EnumType>(&spec.node)) {
            for (const ast::EnumValue& value : enumeration->values) {
                const Symbol& symbol = model_.add({.kind = SymbolKind::EnumValue,
                                                   .name = value.name.name,
                                                   .declared = value.name.range,
                                                   .enum_value = &value,
                                                   .owner = owner});
                if (members != nullptr) {
                    state_.declare(*members, symbol);
                }
                state_.enum_values[fold_case(value.name.name)].push_back(&symbol);
            }
        } else if (const auto* structure = std::get_if<ast::StructType>(&spec.node)) {
            Scope& scope = members != nullptr ? *members : model_.add_scope(nullptr);
            model_.set_struct_members(spec, scope);
            for (const ast::VariableDeclaration& member : structure->members) {
                collect_variable(scope, member, ast::VarSectionKind::Var);
            }
        } else if (const auto* array = std::get_if<ast::ArrayType>(&spec.node)) {
            collect_type_spec(*array->element, nullptr, nullptr);
        } else if (const auto* reference = std::get_if<ast::ReferenceType>(&spec.node)) {
            collect_type_spec(*reference->target, nullptr, nullptr);
        }
    }

    void collect_variable(Scope& scope, const ast::VariableDeclaration& declaration,
                          ast::VarSectionKind section) {
        for (const ast::Identifier& name : declaration.names) {
            state_.declare(scope, model_.add({.kind = SymbolKind::Variable,
                                              .name = name.name,
                                              .declared = name.range,
                                              .section = section,
                                              .variable = &declaration}));
        }
        collect_type_spec(declaration.type, nullptr, nullptr);
    }

    void collect_sections(Scope& scope, const std::vector<ast::DeclarationSection>& sections) {
        for (const ast::DeclarationSection& section : sections) {
            if (const auto* variables = std::get_if<ast::VarSection>(&section)) {
                for (const ast::VariableDeclaration& declaration : variables->variables) {
                    collect_variable(scope, declaration, variables->kind);
                }
            }
        }
    }

    void collect_pou(const ast::Pou& pou) {
        Scope& scope = model_.add_scope(&model_.global_scope());
        state_.pou_scopes[&pou] = &scope;
        state_.declare(model_.global_scope(), model_.add({.kind = SymbolKind::Pou,
                                                          .name = pou.name.name,
                                                          .declared = pou.name.range,
                                                          .pou = &pou,
                                                          .members = &scope}));
        collect_sections(scope, pou.sections);
    }

    /// Configuration and resource globals join the global scope, where programs reach them
    /// through VAR_EXTERNAL (ed. 3, 6.5.2.2).
    void collect_configuration(const ast::Configuration& configuration) {
        state_.declare(model_.global_scope(), model_.add({.kind = SymbolKind::Configuration,
                                                          .name = configuration.name.name,
                                                          .declared = configuration.name.range}));
        collect_sections(model_.global_scope(), configuration.sections);
        Scope& connections = model_.add_scope(&model_.global_scope());
        state_.connection_scopes[&configuration] = &connections;
        for (const ast::Resource& resource : configuration.resources) {
            collect_sections(model_.global_scope(), resource.sections);
            Scope& scope = model_.add_scope(nullptr);
            state_.resource_scopes[&resource] = &scope;
            for (const ast::TaskDeclaration& task : resource.tasks) {
                state_.declare(scope, model_.add({.kind = SymbolKind::Task,
                                                  .name = task.name.name,
                                                  .declared = task.name.range,
                                                  .task = &task}));
            }
            for (const ast::ProgramInstance& instance : resource.programs) {
                const Symbol& symbol = model_.add({.kind = SymbolKind::ProgramInstance,
                                                   .name = instance.name.name,
                                                   .declared = instance.name.range,
                                                   .program_instance = &instance});
                state_.declare(scope, symbol);
                state_.declare(connections, symbol);
            }
        }
    }

    ResolverState& state_;
    SemanticModel& model_;
};

} // namespace

void collect_declarations(std::span<const ast::CompilationUnit> units, ResolverState& state) {
    DeclarationCollector collector(state);
    for (const ast::CompilationUnit& unit : units) {
        collector.collect(unit);
    }
}

} // namespace eposp::compiler::sema
