// E0411: an array's initial values, repetitions counted (`[3(0), 1]` is four), are at most as
// many as its elements (IEC 61131-3 ed. 3, 6.4.4.5); fewer leave the rest at their defaults.
// Every initial value is looked at: of variables (in the POUs whose code runs), globals, and
// the members and defaults of declared types.

#include "../types/constant_folder.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::compiler::checks {
namespace {

class InitialValueCounts {
public:
    explicit InitialValueCounts(const ProgramUnderCheck& check) : check_(check) {}

    void sections(const std::vector<ast::DeclarationSection>& sections) {
        for (const ast::DeclarationSection& section : sections) {
            if (const auto* variables = std::get_if<ast::VarSection>(&section)) {
                for (const ast::VariableDeclaration& declaration : variables->variables) {
                    variable(declaration);
                }
            }
        }
    }

    void type_declaration(const ast::TypeDeclaration& declaration) {
        type_spec(declaration.type);
        if (declaration.initial_value) {
            const sema::Symbol* symbol =
                check_.program.model().global().find_member(declaration.name.name);
            initializer(*declaration.initial_value,
                        symbol != nullptr && symbol->type == &declaration
                            ? check_.program.types().named(*symbol)
                            : check_.program.types().resolve(declaration.type));
        }
    }

private:
    void variable(const ast::VariableDeclaration& declaration) {
        type_spec(declaration.type);
        if (declaration.initial_value) {
            initializer(*declaration.initial_value,
                        check_.program.types().resolve(declaration.type));
        }
    }

    // The members of an inline STRUCT have initial values of their own.
    void type_spec(const ast::TypeSpec& spec) {
        if (const auto* structure = std::get_if<ast::StructType>(&spec.node)) {
            for (const ast::VariableDeclaration& member : structure->members) {
                variable(member);
            }
        } else if (const auto* array = std::get_if<ast::ArrayType>(&spec.node)) {
            type_spec(*array->element);
        }
    }

    void initializer(const ast::Initializer& initializer, const sema::Type* type) {
        if (type == nullptr) {
            return;
        }
        if (const auto* elements =
                std::get_if<std::vector<ast::ArrayInitElement>>(&initializer.value)) {
            if (type->kind != sema::TypeKind::Array || type->element == nullptr) {
                return; // not an array: E0301
            }
            const std::uint64_t count =
                type->size / std::max<std::uint32_t>(type->element->size, 1);
            std::uint64_t values = 0;
            for (const ast::ArrayInitElement& element : *elements) {
                const auto repeat =
                    element.repeat_count
                        ? check_.program.constants().fold_integer(*element.repeat_count)
                        : std::optional<std::int64_t>(1);
                if (!repeat || *repeat < 0) {
                    return; // E0313
                }
                values += static_cast<std::uint64_t>(*repeat);
                if (element.value) {
                    this->initializer(*element.value, type->element);
                }
            }
            if (values > count) {
                check_.diagnostics.error(
                    DiagnosticCode::E0411, initializer.range,
                    fmt::format("too many initial values for {}: {} for {} element{}", type->name,
                                values, count, count == 1 ? "" : "s"));
            }
        } else if (const auto* members =
                       std::get_if<std::vector<ast::StructInitElement>>(&initializer.value)) {
            for (const ast::StructInitElement& member : *members) {
                const sema::Field* field = type->field(member.member.name);
                if (member.value && field != nullptr) {
                    this->initializer(*member.value, field->type);
                }
            }
        }
    }

    const ProgramUnderCheck& check_;
};

} // namespace

void check_initial_value_counts(const ProgramUnderCheck& check,
                                std::span<const ast::CompilationUnit> units) {
    InitialValueCounts counts(check);
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::TypeDeclaration& declaration : unit.types) {
            counts.type_declaration(declaration);
        }
        counts.sections(unit.global_variable_lists);
        for (const ast::Configuration& configuration : unit.configurations) {
            counts.sections(configuration.sections);
            for (const ast::Resource& resource : configuration.resources) {
                counts.sections(resource.sections);
            }
        }
        for (const ast::Pou& pou : unit.pous) {
            if (check.includes(&pou)) {
                counts.sections(pou.sections);
            }
        }
    }
}

} // namespace eposp::compiler::checks
