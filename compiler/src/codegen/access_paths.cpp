// VAR_ACCESS (IEC 61131-3 ed. 3, 6.5.2.2 and 6.8.1): an access path names a variable of the
// configuration for remote access. Each one becomes a symbol named after it, so watch, write
// and force find it by that name; a READ_ONLY one refuses online writes and forces.

#include "program_generator.hpp"

namespace eposp::compiler::codegen {

void ProgramGenerator::publish_access_paths(const ast::Configuration& configuration) {
    auto publish = [&](const std::vector<ast::DeclarationSection>& sections) {
        for (const ast::DeclarationSection& section : sections) {
            if (const auto* access = std::get_if<ast::AccessSection>(&section)) {
                for (const ast::AccessDeclaration& declaration : access->paths) {
                    publish_access_path(declaration);
                }
            }
        }
    };
    publish(configuration.sections);
    for (const ast::Resource& resource : configuration.resources) {
        publish(resource.sections);
    }
}

void ProgramGenerator::publish_access_path(const ast::AccessDeclaration& declaration) {
    // Its name and type are the typing stage's rules (types/access_paths.cpp).
    const auto target = access_path_target(declaration);
    if (!target) {
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
ProgramGenerator::access_path_target(const ast::AccessDeclaration& declaration) {
    if (const auto* address = std::get_if<ast::DirectAddress>(&declaration.path)) {
        return direct_variable(*address);
    }
    // The variable the typing stage found, laid out here: its members' offsets are this type
    // table's.
    const types::AccessPath* path = typed_.access_path(declaration);
    if (path == nullptr) {
        refused_by_checks(DiagnosticCode::E0201); // types/access_paths.cpp
        return std::nullopt;
    }
    const auto instance = instances_.find(path->variable);
    std::optional<Place> place =
        instance != instances_.end() ? std::optional(instance->second) : global(path->variable);
    for (const std::string& member : path->members) {
        const sema::Field* field = place ? place->type->field(member) : nullptr;
        if (field == nullptr) {
            place = std::nullopt;
            break;
        }
        place =
            Place::direct(*field->type, shifted(place->operand, field->offset), place->writable);
    }
    if (!place) {
        refused_by_checks(DiagnosticCode::E0201); // types/access_paths.cpp
    }
    return place;
}

} // namespace eposp::compiler::codegen
