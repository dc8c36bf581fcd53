#include "compile_option_passes.hpp"
#include "eposp/compiler/sema/symbol.hpp"

#include <fmt/format.h>
#include <string>
#include <unordered_map>

namespace eposp::compiler::options {
namespace {

/// Folded name of a substituted FUNCTION_BLOCK → the name of its double as the option spells it.
using Renames = std::unordered_map<std::string, std::string>;

const ast::Pou* find_pou(std::span<const ast::CompilationUnit> units, const std::string& folded) {
    for (const ast::CompilationUnit& unit : units) {
        for (const ast::Pou& pou : unit.pous) {
            if (sema::fold_case(pou.name.name) == folded) {
                return &pou;
            }
        }
    }
    return nullptr;
}

const char* kind_name(ast::PouKind kind) {
    switch (kind) {
    case ast::PouKind::Function:
        return "a FUNCTION";
    case ast::PouKind::FunctionBlock:
        return "a FUNCTION_BLOCK";
    case ast::PouKind::Program:
        return "a PROGRAM";
    }
    return "a POU";
}

/// Checks that both sides of every substitution name a FUNCTION_BLOCK and that no double is
/// itself replaced (one rename per use, so a chain would leave a use of a removed FB).
Renames checked_renames(std::span<const ast::CompilationUnit> units,
                        std::span<const ast::CompilationUnit> built_in,
                        const CompileOptions& options, Diagnostics& diagnostics) {
    Renames renames;
    const auto check = [&](const std::string& name, const std::string& original,
                           const std::string& double_name) {
        const std::string folded = sema::fold_case(name);
        const ast::Pou* pou = find_pou(units, folded);
        if (pou == nullptr) {
            pou = find_pou(built_in, folded);
        }
        if (pou == nullptr) {
            diagnostics.error(DiagnosticCode::E0003, kOptionRange,
                              fmt::format("substitutions: no FUNCTION_BLOCK named '{}' "
                                          "(substituting '{}' by '{}')",
                                          name, original, double_name));
        } else if (pou->kind != ast::PouKind::FunctionBlock) {
            diagnostics.error(DiagnosticCode::E0003, kOptionRange,
                              fmt::format("substitutions: '{}' is {}, not a FUNCTION_BLOCK "
                                          "(substituting '{}' by '{}')",
                                          name, kind_name(pou->kind), original, double_name));
        }
    };
    for (const auto& [original, double_name] : options.substitutions) {
        check(original, original, double_name);
        check(double_name, original, double_name);
        const std::string folded = sema::fold_case(original);
        if (folded == sema::fold_case(double_name)) {
            diagnostics.error(
                DiagnosticCode::E0003, kOptionRange,
                fmt::format("substitutions: '{}' cannot stand in for itself", original));
        } else if (!renames.emplace(folded, double_name).second) {
            diagnostics.error(DiagnosticCode::E0003, kOptionRange,
                              fmt::format("substitutions: '{}' is substituted twice", original));
        }
    }
    for (const auto& [original, double_name] : options.substitutions) {
        if (renames.contains(sema::fold_case(double_name))) {
            diagnostics.error(DiagnosticCode::E0003, kOptionRange,
                              fmt::format("substitutions: '{}' stands in for '{}' and is "
                                          "substituted itself",
                                          double_name, original));
        }
    }
    return renames;
}

/// Renames the FB types named anywhere a type is written.
class TypeRenamer {
public:
    explicit TypeRenamer(const Renames& renames) : renames_(renames) {}

    void rename(ast::CompilationUnit& unit) const {
        for (ast::TypeDeclaration& declaration : unit.types) {
            rename(declaration.type);
        }
        for (ast::Pou& pou : unit.pous) {
            if (pou.return_type) {
                rename(*pou.return_type);
            }
            if (pou.extends) {
                rename(*pou.extends);
            }
            rename(pou.sections);
        }
        for (ast::Configuration& configuration : unit.configurations) {
            rename(configuration.sections);
            for (ast::Resource& resource : configuration.resources) {
                rename(resource.sections);
            }
        }
        rename(unit.global_variable_lists);
    }

private:
    void rename(ast::Identifier& name) const {
        if (const auto it = renames_.find(sema::fold_case(name.name)); it != renames_.end()) {
            name.name = it->second;
        }
    }

    void rename(std::vector<ast::DeclarationSection>& sections) const {
        for (ast::DeclarationSection& section : sections) {
            if (auto* variables = std::get_if<ast::VarSection>(&section)) {
                for (ast::VariableDeclaration& declaration : variables->variables) {
                    rename(declaration.type);
                }
            } else {
                for (ast::AccessDeclaration& path : std::get<ast::AccessSection>(section).paths) {
                    rename(path.type);
                }
            }
        }
    }

    void rename(ast::TypeSpec& spec) const {
        if (auto* named = std::get_if<ast::NamedTypeRef>(&spec.node)) {
            rename(named->name);
        } else if (auto* array = std::get_if<ast::ArrayType>(&spec.node)) {
            rename(*array->element);
        } else if (auto* reference = std::get_if<ast::ReferenceType>(&spec.node)) {
            rename(*reference->target);
        } else if (auto* structure = std::get_if<ast::StructType>(&spec.node)) {
            for (ast::VariableDeclaration& member : structure->members) {
                rename(member.type);
            }
        }
    }

    const Renames& renames_;
};

} // namespace

void substitute_function_blocks(std::vector<ast::CompilationUnit>& units,
                                std::span<const ast::CompilationUnit> built_in,
                                const CompileOptions& options, Diagnostics& diagnostics) {
    if (options.substitutions.empty()) {
        return;
    }
    const std::size_t errors = diagnostics.error_count();
    const Renames renames = checked_renames(units, built_in, options, diagnostics);
    if (diagnostics.error_count() != errors) {
        return;
    }
    const TypeRenamer renamer(renames);
    for (ast::CompilationUnit& unit : units) {
        renamer.rename(unit);
        // Nothing names the original any more: its body is neither checked nor generated.
        std::erase_if(unit.pous, [&](const ast::Pou& pou) {
            return pou.kind == ast::PouKind::FunctionBlock &&
                   renames.contains(sema::fold_case(pou.name.name));
        });
    }
}

} // namespace eposp::compiler::options
