// E0423, E0401: what a program connection (IEC 61131-3 ed. 3, 6.8.2: `PROGRAM inst WITH t : P
// (in := source, out => sink)`) may name. An input reads a global variable or a part of one, a
// constant, a direct address or an output of another program instance; an output writes a
// global variable or a part of one, or a direct output or memory address.

#include "program_connections.hpp"

#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"
#include "writable_targets.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {
namespace {

// The type of the program instance `symbol` names: its inputs and outputs.
const sema::Type* instance_type(const sema::SemanticModel& model, sema::TypeTable& types,
                                const sema::Symbol& symbol) {
    const sema::Symbol* type = symbol.program_instance != nullptr
                                   ? model.resolved(symbol.program_instance->type)
                                   : nullptr;
    return type != nullptr && type->kind == sema::SymbolKind::Pou ? types.instance(*type->pou)
                                                                  : nullptr;
}

void check_connections(types::TypedProgram& program, const ast::ProgramInstance& instance,
                       const ast::Pou& pou, Diagnostics& diagnostics) {
    const sema::Type* type = program.types().instance(pou);
    for (const ast::Argument& argument : instance.connections) {
        const bool output = argument.kind == ast::Argument::Kind::Output;
        const sema::Field* field =
            type != nullptr && argument.name ? type->field(argument.name->name) : nullptr;
        if (field == nullptr ||
            field->section != (output ? ast::VarSectionKind::Output : ast::VarSectionKind::Input)) {
            continue; // no such input or output: E0210
        }
        if (!is_connectable(program.model(), program.types(), *argument.value, output)) {
            diagnostics.error(DiagnosticCode::E0423, argument.value->range,
                              output ? "an output connects to a global variable (or a part of "
                                       "one) or a direct output or memory address"
                                     : "an input connects to a global variable (or a part of "
                                       "one), a constant, a direct address or an output of "
                                       "another program");
        } else if (auto note = output ? unwritable(program, *argument.value) : std::nullopt) {
            Diagnostic diagnostic{
                DiagnosticCode::E0401, argument.value->range,
                fmt::format("'{}' cannot be connected to a constant", field->name)};
            diagnostic.notes.push_back(std::move(*note));
            diagnostics.report(std::move(diagnostic));
        }
    }
}

} // namespace

bool is_connectable(const sema::SemanticModel& model, sema::TypeTable& types,
                    const ast::Expression& expression, bool output) {
    const ast::Expression* path = &expression;
    if (const auto* negated = std::get_if<ast::UnaryExpression>(&path->node)) {
        path = negated->operand.get(); // `-5`
        if (!std::holds_alternative<ast::LiteralExpression>(path->node)) {
            return false;
        }
    }
    if (std::holds_alternative<ast::LiteralExpression>(path->node)) {
        return !output;
    }
    // Down a variable path to its root: `g`, `g.x`, `arr[2]`, `Inst1.out`, `%QX0.0`.
    for (;;) {
        if (const auto* member = std::get_if<ast::MemberExpression>(&path->node)) {
            const auto* object = std::get_if<ast::NameExpression>(&member->object->node);
            const sema::Symbol* symbol = object != nullptr ? model.resolved(object->name) : nullptr;
            if (symbol != nullptr && symbol->kind == sema::SymbolKind::ProgramInstance) {
                const sema::Type* instance = instance_type(model, types, *symbol);
                const sema::Field* field =
                    instance != nullptr ? instance->field(member->member.name) : nullptr;
                if (output || field == nullptr || field->section != ast::VarSectionKind::Output) {
                    return false; // only read, and only its outputs
                }
            }
            path = member->object.get();
        } else if (const auto* element = std::get_if<ast::IndexExpression>(&path->node)) {
            path = element->array.get();
        } else {
            break;
        }
    }
    if (const auto* direct = std::get_if<ast::DirectAddressExpression>(&path->node)) {
        return !output || direct->address.area != ast::DirectAddress::Area::Input;
    }
    return std::holds_alternative<ast::NameExpression>(path->node);
}

void check_program_connections(types::TypedProgram& program,
                               std::span<const ast::CompilationUnit> units,
                               Diagnostics& diagnostics) {
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Configuration& configuration : unit.configurations) {
            for (const ast::Resource& resource : configuration.resources) {
                for (const ast::ProgramInstance& instance : resource.programs) {
                    const sema::Symbol* symbol = program.model().resolved(instance.type);
                    if (symbol != nullptr && symbol->kind == sema::SymbolKind::Pou) {
                        check_connections(program, instance, *symbol->pou, diagnostics);
                    }
                }
            }
        }
    }
}

} // namespace eposp::compiler::checks
