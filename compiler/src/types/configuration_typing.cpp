// A CONFIGURATION typed: its globals, its program instances' connections (6.8.2); its access
// paths are access_paths.cpp's.

#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"

#include <fmt/format.h>

namespace eposp::compiler::types {

const sema::Type& ExpressionTyper::address_type(const ast::DirectAddress& address) {
    // 6.5.5: the size prefix is the type (X or none BOOL, B BYTE, W WORD, ...).
    static constexpr E kBySize[] = {E::Bool, E::Bool, E::Byte, E::Word, E::Dword, E::Lword};
    return elementary(kBySize[static_cast<int>(address.size)]);
}

void ExpressionTyper::configuration(const ast::Configuration& configuration) {
    access_paths(configuration);
    sections(configuration.sections);
    for (const ast::Resource& resource : configuration.resources) {
        sections(resource.sections);
        for (const ast::ProgramInstance& instance : resource.programs) {
            connections(instance);
        }
    }
}

const sema::Type* ExpressionTyper::program_instance(const ast::ProgramInstance& instance) {
    const sema::Symbol* program = model_.resolved(instance.type);
    return program != nullptr && program->kind == sema::SymbolKind::Pou
               ? program_.types().instance(*program->pou)
               : nullptr;
}

void ExpressionTyper::connections(const ast::ProgramInstance& instance) {
    // 6.8.2: a source is stored into the program's input, an output into its sink; what they
    // may name is the checking stage's (checks/program_connections.cpp).
    const sema::Type* type = program_instance(instance);
    for (const ast::Argument& connection : instance.connections) {
        const bool output = connection.kind == ast::Argument::Kind::Output;
        const sema::Field* field =
            type != nullptr && connection.name ? type->field(connection.name->name) : nullptr;
        if (field == nullptr ||
            field->section != (output ? ast::VarSectionKind::Output : ast::VarSectionKind::Input)) {
            if (type != nullptr) {
                diagnostics_.error(DiagnosticCode::E0210, connection.range,
                                   fmt::format("'{}' has no {} of that name", type->name,
                                               output ? "output" : "input"));
            }
            this->type(*connection.value, nullptr);
            continue;
        }
        if (!output) {
            expect(*connection.value, *field->type, "a value");
            continue;
        }
        const sema::Type* sink = this->type(*connection.value, nullptr);
        if (sink != nullptr && !sema::converts_implicitly(*field->type, *sink)) {
            diagnostics_.error(DiagnosticCode::E0301, connection.value->range,
                               mismatch("a value", *field->type, *sink));
        }
    }
}

} // namespace eposp::compiler::types
