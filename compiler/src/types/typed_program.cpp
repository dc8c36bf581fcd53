#include "eposp/compiler/types/typed_program.hpp"

#include "constant_folder.hpp"
#include "expression_typer.hpp"

#include <unordered_set>

namespace eposp::compiler::types {

TypedProgram::TypedProgram(const sema::SemanticModel& model,
                           std::function<const ast::Pou*(std::string_view)> library,
                           std::function<bool(const ast::VariableDeclaration&)> is_constant,
                           Diagnostics& diagnostics)
    : model_(model), library_(library), is_constant_(is_constant),
      folder_(std::make_unique<ConstantFolder>(*this, types_)),
      types_(model, diagnostics, std::move(library), std::move(is_constant), *folder_) {}

TypedProgram::~TypedProgram() = default;

const sema::Type* TypedProgram::type_of(const ast::Expression& expression) const {
    return types_of_.find(&expression);
}

const Constant* TypedProgram::constant_of(const ast::Expression& expression) const {
    return constants_.find(&expression);
}

const CallTarget* TypedProgram::call_target(const ast::Expression& expression) const {
    return calls_.find(&expression);
}

void TypedProgram::set_type(const ast::Expression& expression, const sema::Type& type) {
    types_of_.set(&expression, &type);
}

const sema::Type* TypedProgram::operands_of(const ast::Expression& expression) const {
    return operands_of_.find(&expression);
}

void TypedProgram::set_operands(const ast::Expression& expression, const sema::Type& type) {
    operands_of_.set(&expression, &type);
}

void TypedProgram::set_constant(const ast::Expression& expression, Constant value) {
    constants_.set(&expression, &constant_values_.emplace_back(std::move(value)));
}

void TypedProgram::set_wraps(const ast::Expression& expression, bool wraps) {
    if (wraps) {
        wrapping_.insert(&expression);
    } else {
        wrapping_.erase(&expression);
    }
}

const AccessPath* TypedProgram::access_path(const ast::AccessDeclaration& declaration) const {
    const auto found = access_paths_.find(&declaration);
    return found != access_paths_.end() ? &found->second : nullptr;
}

void TypedProgram::set_access_path(const ast::AccessDeclaration& declaration, AccessPath path) {
    access_paths_.insert_or_assign(&declaration, std::move(path));
}

void TypedProgram::set_call(const ast::Expression& expression, CallTarget target) {
    calls_.set(&expression, &call_targets_.emplace_back(std::move(target)));
}

namespace {

void collect_constants(const std::vector<ast::DeclarationSection>& sections,
                       std::unordered_set<const ast::VariableDeclaration*>& constants) {
    for (const ast::DeclarationSection& section : sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables != nullptr && variables->constant) {
            for (const ast::VariableDeclaration& declaration : variables->variables) {
                constants.insert(&declaration);
            }
        }
    }
}

} // namespace

std::unique_ptr<TypedProgram> type_program(std::span<const ast::CompilationUnit> units,
                                           const sema::SemanticModel& model,
                                           std::function<const ast::Pou*(std::string_view)> library,
                                           Diagnostics& diagnostics) {
    auto constants = std::make_shared<std::unordered_set<const ast::VariableDeclaration*>>();
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Pou& pou : unit.pous) {
            collect_constants(pou.sections, *constants);
        }
        collect_constants(unit.global_variable_lists, *constants);
        for (const ast::Configuration& configuration : unit.configurations) {
            collect_constants(configuration.sections, *constants);
            for (const ast::Resource& resource : configuration.resources) {
                collect_constants(resource.sections, *constants);
            }
        }
    }
    auto program = std::make_unique<TypedProgram>(
        model, std::move(library),
        [constants](const ast::VariableDeclaration& declaration) {
            return constants->contains(&declaration);
        },
        diagnostics);
    ExpressionTyper typer(*program, model, diagnostics);
    // Declarations first, so that a constant's value is known wherever it is used.
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::TypeDeclaration& declaration : unit.types) {
            typer.type_declaration(declaration);
        }
    }
    for (const ast::CompilationUnit& unit : units) {
        typer.sections(unit.global_variable_lists);
        for (const ast::Configuration& configuration : unit.configurations) {
            typer.configuration(configuration);
        }
    }
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Pou& pou : unit.pous) {
            typer.pou(pou);
        }
    }
    return program;
}

void type_library(TypedProgram& program, std::span<const ast::CompilationUnit> units,
                  const sema::SemanticModel& model, Diagnostics& diagnostics) {
    ExpressionTyper typer(program, model, diagnostics);
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Pou& pou : unit.pous) {
            typer.pou(pou);
        }
    }
}

} // namespace eposp::compiler::types
