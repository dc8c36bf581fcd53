// E0401: what a statement writes is a variable it may write (IEC 61131-3 ed. 3, 6.5.2.2 and
// 7.3.3.2): not a CONSTANT, not an output of another instance (only the instance writes it), not
// a direct input address (the process image writes it). Assignments (also to a bit of a word),
// `=>` bindings and VAR_IN_OUT connections are checked here; program connections in
// program_connections.cpp.

#include "writable_targets.hpp"

#include "calls.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

#include <fmt/format.h>

namespace eposp::compiler::checks {
namespace {

DiagnosticNote constant_note(const ast::VariableDeclaration& declaration, const std::string& name) {
    return {declaration.range, fmt::format("'{}' is declared CONSTANT here", name)};
}

std::optional<DiagnosticNote> unwritable_name(types::TypedProgram& program,
                                              const ast::NameExpression& name) {
    const sema::Symbol* symbol = program.model().resolved(name.name);
    if (symbol == nullptr || symbol->kind != sema::SymbolKind::Variable ||
        symbol->variable == nullptr) {
        return std::nullopt; // a program instance, the function's result, or the names' error
    }
    if (program.is_constant(*symbol->variable)) {
        return constant_note(*symbol->variable, symbol->name);
    }
    if (symbol->section == ast::VarSectionKind::External) {
        const sema::Symbol* global = program.model().global().find(symbol->name);
        if (global != nullptr && global->kind == sema::SymbolKind::Variable &&
            global->variable != nullptr && program.is_constant(*global->variable)) {
            return constant_note(*global->variable, global->name);
        }
    }
    return std::nullopt;
}

std::optional<DiagnosticNote> unwritable_member(types::TypedProgram& program,
                                                const ast::MemberExpression& member) {
    const auto* object = std::get_if<ast::NameExpression>(&member.object->node);
    const sema::Symbol* symbol =
        object != nullptr ? program.model().resolved(object->name) : nullptr;
    if (symbol != nullptr && symbol->kind == sema::SymbolKind::Pou &&
        symbol->pou->kind == ast::PouKind::Program) {
        // `P.x` (CODESYS) reaches all of P's variables but its constants.
        const sema::Type* instance = program.types().instance(*symbol->pou);
        const sema::Field* field =
            instance != nullptr ? instance->field(member.member.name) : nullptr;
        return field != nullptr && field->declaration != nullptr &&
                       program.is_constant(*field->declaration)
                   ? std::optional(constant_note(*field->declaration, field->name))
                   : std::nullopt;
    }
    const sema::Type* type = program.type_of(*member.object);
    const sema::Field* field = type != nullptr && (type->kind == sema::TypeKind::Struct ||
                                                   type->kind == sema::TypeKind::Instance)
                                   ? type->field(member.member.name)
                                   : nullptr;
    if (field == nullptr) {
        return unwritable(program, *member.object);
    }
    if (type->kind == sema::TypeKind::Instance && field->section == ast::VarSectionKind::Output) {
        return DiagnosticNote{field->declaration != nullptr ? field->declaration->range
                                                            : member.member.range,
                              fmt::format("'{}' is an output of '{}': only the instance writes it",
                                          field->name, type->name)};
    }
    return unwritable(program, *member.object);
}

void check_target(const PouUnderCheck& check, const ast::Expression& target,
                  const SourceRange& range, std::string message) {
    if (auto note = unwritable(check.program, target)) {
        Diagnostic diagnostic{DiagnosticCode::E0401, range, std::move(message)};
        diagnostic.notes.push_back(std::move(*note));
        check.diagnostics.report(std::move(diagnostic));
    }
}

// A READ_WRITE access path's variable: a program instance's (all of it is reachable), or a global
// one that is not CONSTANT; a direct address that is not an input.
std::optional<DiagnosticNote> unwritable_path(types::TypedProgram& program,
                                              const ast::Configuration& configuration,
                                              const ast::AccessDeclaration& declaration) {
    if (const auto* address = std::get_if<ast::DirectAddress>(&declaration.path)) {
        return address->area == ast::DirectAddress::Area::Input
                   ? std::optional(DiagnosticNote{address->range, "an input address is written "
                                                                  "by the process image"})
                   : std::nullopt;
    }
    const auto& names = std::get<std::vector<ast::Identifier>>(declaration.path);
    std::size_t first = 0;
    for (const ast::Resource& resource : configuration.resources) {
        if (names.size() > 1 &&
            sema::fold_case(resource.name.name) == sema::fold_case(names.front().name)) {
            first = 1; // a leading resource name only says where the variable is
        }
        for (const ast::ProgramInstance& instance : resource.programs) {
            if (sema::fold_case(instance.name.name) == sema::fold_case(names[first].name)) {
                return std::nullopt;
            }
        }
    }
    const sema::Symbol* global = program.model().global().find(names[first].name);
    return global != nullptr && global->kind == sema::SymbolKind::Variable &&
                   global->variable != nullptr && program.is_constant(*global->variable)
               ? std::optional(constant_note(*global->variable, global->name))
               : std::nullopt;
}

// What a call writes: every `=>` binding (ENO too) and every VAR_IN_OUT, which the callee
// writes through the reference the call connects.
void check_call_arguments(const PouUnderCheck& check, const ast::CallExpression& call) {
    const Callee callee = callee_of(check.program, call);
    std::size_t positional = 0;
    for (const ast::Argument& argument : call.arguments) {
        if (argument.kind == ast::Argument::Kind::Output) {
            check_target(check, *argument.value, argument.value->range,
                         is_enable_argument(argument)
                             ? "ENO cannot be written to this variable (a constant, an input or "
                               "an output of another instance)"
                             : "this output cannot be written to this variable (a constant, an "
                               "input address or an output of another instance)");
            continue;
        }
        // An FB call's positional arguments connect nothing (E0415).
        const bool connects = callee.frame != nullptr && !is_enable_argument(argument) &&
                              (callee.kind != Callee::Kind::Instance || argument.name);
        const sema::Field* formal =
            connects ? sema::formal_parameter(*callee.frame, argument, positional) : nullptr;
        if (formal != nullptr && formal->section == ast::VarSectionKind::InOut) {
            check_target(check, *argument.value, argument.value->range,
                         fmt::format("VAR_IN_OUT '{}' is written through this connection: it "
                                     "needs a variable that can be written",
                                     formal->name));
        }
    }
}

} // namespace

std::optional<DiagnosticNote> unwritable(types::TypedProgram& program,
                                         const ast::Expression& target) {
    if (const auto* name = std::get_if<ast::NameExpression>(&target.node)) {
        return unwritable_name(program, *name);
    }
    if (const auto* member = std::get_if<ast::MemberExpression>(&target.node)) {
        return unwritable_member(program, *member);
    }
    if (const auto* element = std::get_if<ast::IndexExpression>(&target.node)) {
        return unwritable(program, *element->array);
    }
    if (const auto* bit = std::get_if<ast::BitAccessExpression>(&target.node)) {
        return unwritable(program, *bit->object);
    }
    if (const auto* direct = std::get_if<ast::DirectAddressExpression>(&target.node);
        direct != nullptr && direct->address.area == ast::DirectAddress::Area::Input) {
        return DiagnosticNote{target.range, "an input address is written by the process image"};
    }
    return std::nullopt; // a dereference writes where the reference points
}

void check_writable_targets(const PouUnderCheck& check) {
    for (const ast::Statement* statement : check.body.assignments()) {
        const ast::Expression& target = *std::get<ast::AssignmentStatement>(statement->node).target;
        if (const auto* bit = std::get_if<ast::BitAccessExpression>(&target.node)) {
            check_target(check, *bit->object, bit->object->range,
                         "this variable cannot be assigned here");
        } else {
            check_target(check, target, target.range,
                         "this variable cannot be assigned here (a constant or an output of "
                         "another instance)");
        }
    }
    for (const ast::Expression* call : check.body.calls()) {
        check_call_arguments(check, std::get<ast::CallExpression>(call->node));
    }
}

void check_writable_access_paths(types::TypedProgram& program,
                                 std::span<const ast::CompilationUnit> units,
                                 Diagnostics& diagnostics) {
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Configuration& configuration : unit.configurations) {
            auto check = [&](const std::vector<ast::DeclarationSection>& sections) {
                for (const ast::DeclarationSection& section : sections) {
                    const auto* access = std::get_if<ast::AccessSection>(&section);
                    if (access == nullptr) {
                        continue;
                    }
                    for (const ast::AccessDeclaration& path : access->paths) {
                        auto note = path.writable ? unwritable_path(program, configuration, path)
                                                  : std::nullopt;
                        if (note) {
                            Diagnostic diagnostic{
                                DiagnosticCode::E0401, path.range,
                                fmt::format("the access path '{}' names a constant: it can only "
                                            "be READ_ONLY",
                                            path.name.name)};
                            diagnostic.notes.push_back(std::move(*note));
                            diagnostics.report(std::move(diagnostic));
                        }
                    }
                }
            };
            check(configuration.sections);
            for (const ast::Resource& resource : configuration.resources) {
                check(resource.sections);
            }
        }
    }
}

} // namespace eposp::compiler::checks
