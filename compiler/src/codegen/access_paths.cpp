// VAR_ACCESS (IEC 61131-3 ed. 3, 6.5.2.2 and 6.8.1): an access path names a variable of the
// configuration for remote access. Each one becomes a symbol named after it, so watch, write
// and force find it by that name; a READ_ONLY one refuses online writes and forces.

#include "eposp/compiler/sema/symbol.hpp"
#include "program_generator.hpp"

#include <fmt/format.h>

namespace eposp::compiler::codegen {

namespace {

std::string joined(const std::vector<ast::Identifier>& names) {
    std::string text;
    for (const ast::Identifier& name : names) {
        text += (text.empty() ? "" : ".") + name.name;
    }
    return text;
}

} // namespace

void ProgramGenerator::publish_access_paths(const ast::Configuration& configuration) {
    auto publish = [&](const std::vector<ast::DeclarationSection>& sections) {
        for (const ast::DeclarationSection& section : sections) {
            if (const auto* access = std::get_if<ast::AccessSection>(&section)) {
                for (const ast::AccessDeclaration& declaration : access->paths) {
                    publish_access_path(configuration, declaration);
                }
            }
        }
    };
    publish(configuration.sections);
    for (const ast::Resource& resource : configuration.resources) {
        publish(resource.sections);
    }
}

void ProgramGenerator::publish_access_path(const ast::Configuration& configuration,
                                           const ast::AccessDeclaration& declaration) {
    const std::string name = sema::fold_case(declaration.name.name);
    // Globals share the configuration's names, and a global variable list's are even
    // published under the same bare names.
    const sema::Symbol* global = program_.model.global().find_member(name);
    if (global != nullptr && global->kind == sema::SymbolKind::Variable) {
        diagnostics_.error(
            DiagnosticCode::E0202, declaration.name.range,
            fmt::format("'{}' is already the name of a global variable", declaration.name.name));
        return;
    }
    if (instances_.contains(name) || !access_names_.insert(name).second) {
        diagnostics_.error(DiagnosticCode::E0202, declaration.name.range,
                           fmt::format("'{}' is already the name of a program instance or an "
                                       "access path",
                                       declaration.name.name));
        return;
    }
    const sema::Type* declared = types_.resolve(declaration.type);
    const auto target = access_path_target(configuration, declaration);
    if (declared == nullptr || !target) {
        return;
    }
    if (!sema::same_type(*declared, *target->type)) {
        diagnostics_.error(DiagnosticCode::E0301, declaration.type.range,
                           fmt::format("the access path '{}' is a {}, not a {}",
                                       declaration.name.name, target->type->name, declared->name));
        return;
    }
    if (declaration.writable && !target->writable) {
        refused_by_checks(DiagnosticCode::E0401); // checks/writable_targets.cpp
        return;
    }
    builder_.symbol(declaration.name.name, type_descriptor(*target->type), target->operand.offset(),
                    !declaration.writable);
}

std::optional<Place>
ProgramGenerator::access_path_target(const ast::Configuration& configuration,
                                     const ast::AccessDeclaration& declaration) {
    if (const auto* address = std::get_if<ast::DirectAddress>(&declaration.path)) {
        return direct_variable(*address);
    }
    const auto& names = std::get<std::vector<ast::Identifier>>(declaration.path);
    const auto unknown = [&] {
        diagnostics_.error(DiagnosticCode::E0201, declaration.range,
                           fmt::format("unknown access path '{}'", joined(names)));
        return std::nullopt;
    };
    std::size_t next = 0;
    // A leading resource name only says where the variable is.
    for (const ast::Resource& resource : configuration.resources) {
        if (names.size() > 1 &&
            sema::fold_case(resource.name.name) == sema::fold_case(names.front().name)) {
            next = 1;
        }
    }
    const std::string first = sema::fold_case(names[next].name);
    std::optional<Place> place;
    if (const auto instance = instances_.find(first); instance != instances_.end()) {
        place = instance->second;
    } else {
        place = global(first);
    }
    if (!place) {
        return unknown();
    }
    for (++next; next < names.size(); ++next) {
        const sema::Type& type = *place->type;
        const sema::Field* field =
            type.kind == sema::TypeKind::Struct || type.kind == sema::TypeKind::Instance
                ? type.field(names[next].name)
                : nullptr;
        if (field == nullptr || field->section == ast::VarSectionKind::InOut) {
            return unknown();
        }
        place =
            Place::direct(*field->type, shifted(place->operand, field->offset), place->writable);
    }
    return place;
}

} // namespace eposp::compiler::codegen
