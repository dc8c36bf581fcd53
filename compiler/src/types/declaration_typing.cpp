// Declarations typed: a POU's sections, TYPE declarations, STRUCT members, and every initial
// value checked against its variable's type and folded as the image holds it (ed. 3, 6.5.1.3).

#include "constant_folder.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"
#include "initial_constant.hpp"

#include <fmt/format.h>

namespace eposp::compiler::types {

void ExpressionTyper::pou(const ast::Pou& pou) {
    current_ = &pou;
    // Its instance or frame first: a declaration that refers to the POU itself (`next :
    // REF_TO Link`) is then laid out inside it.
    if (pou.kind == ast::PouKind::Function) {
        program_.types().frame(pou);
    } else {
        program_.types().instance(pou);
    }
    sections(pou.sections);
    statements(pou.body);
    current_ = nullptr;
}

void ExpressionTyper::sections(const std::vector<ast::DeclarationSection>& sections) {
    for (const ast::DeclarationSection& section : sections) {
        const auto* variables = std::get_if<ast::VarSection>(&section);
        if (variables == nullptr) {
            continue;
        }
        for (const ast::VariableDeclaration& declaration : variables->variables) {
            type_spec(declaration.type);
            if (!declaration.initial_value) {
                continue;
            }
            const sema::Type* type = program_.types().resolve(declaration.type);
            if (!variables->constant) {
                initializer(*declaration.initial_value, type);
                continue;
            }
            // A use of the CONSTANT in its own initial value is none (circular()).
            defining_ = &declaration;
            program_.constants().defining(declaration,
                                          [&] { initializer(*declaration.initial_value, type); });
            defining_ = nullptr;
        }
    }
}

void ExpressionTyper::type_declaration(const ast::TypeDeclaration& declaration) {
    type_spec(declaration.type);
    // By its name (`Pct`), which its diagnostics say; laid out even when nothing uses it, so
    // that its errors are reported.
    const sema::Symbol* symbol = model_.global().find_member(declaration.name.name);
    const sema::Type* type = symbol != nullptr && symbol->type == &declaration
                                 ? program_.types().named(*symbol)
                                 : program_.types().resolve(declaration.type);
    if (declaration.initial_value) {
        initializer(*declaration.initial_value, type);
    }
}

void ExpressionTyper::type_spec(const ast::TypeSpec& spec) {
    // Members of a STRUCT, inline or declared, have initial values of their own.
    if (const auto* structure = std::get_if<ast::StructType>(&spec.node)) {
        for (const ast::VariableDeclaration& member : structure->members) {
            type_spec(member.type);
            if (member.initial_value) {
                initializer(*member.initial_value, program_.types().resolve(member.type));
            }
        }
    } else if (const auto* array = std::get_if<ast::ArrayType>(&spec.node)) {
        type_spec(*array->element);
    }
}

void ExpressionTyper::initializer(const ast::Initializer& initializer, const sema::Type* target) {
    if (target == nullptr) {
        return;
    }
    if (const auto* expression = std::get_if<ast::ExpressionPtr>(&initializer.value)) {
        const std::size_t errors = diagnostics_.error_count();
        store(**expression, *target, "an initial value");
        // The image holds the value folded (a constant defined through itself has none): what
        // code generation writes (codegen/initial_values.cpp).
        if (errors == diagnostics_.error_count()) {
            const auto bytes = constant_bytes(**expression, *target, program_);
            if (const auto* refusal = std::get_if<ConstantRefusal>(&bytes)) {
                const bool circular = defining_ != nullptr &&
                                      refusal->code == DiagnosticCode::E0313 &&
                                      program_.constants().circular(*defining_);
                diagnostics_.error(refusal->code, (*expression)->range,
                                   circular
                                       ? fmt::format("the constant '{}' is defined through itself",
                                                     defining_->names.front().name)
                                       : refusal->message);
            }
        }
    } else if (const auto* elements =
                   std::get_if<std::vector<ast::ArrayInitElement>>(&initializer.value)) {
        if (target->kind != sema::TypeKind::Array) {
            diagnostics_.error(DiagnosticCode::E0301, initializer.range,
                               fmt::format("{} is not an array", target->name));
            return;
        }
        for (const ast::ArrayInitElement& element : *elements) {
            if (element.repeat_count) {
                const std::size_t errors = diagnostics_.error_count();
                type(*element.repeat_count, &elementary(E::Dint));
                if (errors == diagnostics_.error_count() &&
                    program_.constants().fold_integer(*element.repeat_count).value_or(-1) < 0) {
                    diagnostics_.error(DiagnosticCode::E0313, element.repeat_count->range,
                                       "a repetition count must be a constant >= 0");
                }
            }
            if (element.value) {
                this->initializer(*element.value, target->element);
            }
        }
    } else {
        for (const ast::StructInitElement& element :
             std::get<std::vector<ast::StructInitElement>>(initializer.value)) {
            const sema::Field* field = target->field(element.member.name);
            if (element.value) {
                this->initializer(*element.value, field != nullptr ? field->type : nullptr);
            }
        }
    }
}

} // namespace eposp::compiler::types
