// VAR_ACCESS (IEC 61131-3 ed. 3, 6.5.2.2 and 6.8.1): an access path names a variable of the
// configuration (`Inst0.count`, `Res1.Inst0.s.x`, a global, `%IW4`) under a name of its own and
// states its type, which must be the variable's.

#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"

#include <fmt/format.h>
#include <set>

namespace eposp::compiler::types {

namespace {

std::string joined(const std::vector<ast::Identifier>& names) {
    std::string text;
    for (const ast::Identifier& name : names) {
        text += (text.empty() ? "" : ".") + name.name;
    }
    return text;
}

} // namespace

void ExpressionTyper::access_paths(const ast::Configuration& configuration) {
    std::set<std::string> names; // the program instances', then the access paths'
    for (const ast::Resource& resource : configuration.resources) {
        for (const ast::ProgramInstance& instance : resource.programs) {
            names.insert(sema::fold_case(instance.name.name));
        }
    }
    const auto paths = [&](const std::vector<ast::DeclarationSection>& sections) {
        for (const ast::DeclarationSection& section : sections) {
            if (const auto* access = std::get_if<ast::AccessSection>(&section)) {
                for (const ast::AccessDeclaration& declaration : access->paths) {
                    access_path(configuration, declaration, names);
                }
            }
        }
    };
    paths(configuration.sections);
    for (const ast::Resource& resource : configuration.resources) {
        paths(resource.sections);
    }
}

void ExpressionTyper::access_path(const ast::Configuration& configuration,
                                  const ast::AccessDeclaration& declaration,
                                  std::set<std::string>& names) {
    const std::string name = sema::fold_case(declaration.name.name);
    // Globals share the configuration's names, and a global variable list's are even published
    // under the same bare names.
    const sema::Symbol* global = model_.global().find_member(name);
    if (global != nullptr && global->kind == sema::SymbolKind::Variable) {
        diagnostics_.error(
            DiagnosticCode::E0202, declaration.name.range,
            fmt::format("'{}' is already the name of a global variable", declaration.name.name));
        return;
    }
    if (!names.insert(name).second) {
        diagnostics_.error(DiagnosticCode::E0202, declaration.name.range,
                           fmt::format("'{}' is already the name of a program instance or an "
                                       "access path",
                                       declaration.name.name));
        return;
    }
    const sema::Type* declared = program_.types().resolve(declaration.type);
    const sema::Type* target = access_path_target(configuration, declaration);
    if (declared != nullptr && target != nullptr && !sema::same_type(*declared, *target)) {
        diagnostics_.error(DiagnosticCode::E0301, declaration.type.range,
                           fmt::format("the access path '{}' is a {}, not a {}",
                                       declaration.name.name, target->name, declared->name));
    }
}

const sema::Type* ExpressionTyper::access_path_target(const ast::Configuration& configuration,
                                                      const ast::AccessDeclaration& declaration) {
    if (const auto* address = std::get_if<ast::DirectAddress>(&declaration.path)) {
        return &address_type(*address);
    }
    const auto& names = std::get<std::vector<ast::Identifier>>(declaration.path);
    const auto unknown = [&] {
        return fail(DiagnosticCode::E0201, declaration.range,
                    fmt::format("unknown access path '{}'", joined(names)));
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
    const sema::Type* type = nullptr;
    for (const ast::Resource& resource : configuration.resources) {
        for (const ast::ProgramInstance& instance : resource.programs) {
            if (sema::fold_case(instance.name.name) == first) {
                type = program_instance(instance);
            }
        }
    }
    if (type == nullptr) {
        const sema::Symbol* global = model_.global().find_member(first);
        type = global != nullptr && global->kind == sema::SymbolKind::Variable
                   ? variable_type(*global)
                   : nullptr;
    }
    AccessPath path{.variable = first, .members = {}};
    for (++next; type != nullptr && next < names.size(); ++next) {
        const sema::Field* field =
            type->kind == sema::TypeKind::Struct || type->kind == sema::TypeKind::Instance
                ? type->field(names[next].name)
                : nullptr;
        type = field != nullptr && field->section != ast::VarSectionKind::InOut ? field->type
                                                                                : nullptr;
        path.members.push_back(names[next].name);
    }
    if (type == nullptr) {
        return unknown();
    }
    // What code generation publishes (codegen/access_paths.cpp).
    program_.set_access_path(declaration, std::move(path));
    return type;
}

} // namespace eposp::compiler::types
