#include "compile_option_passes.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::compiler::options {
namespace {

// The VAR_GLOBALs of the configurations (and of their resources) stay as global variable lists:
// the POUs of the file refer to them (VAR_EXTERNAL) and the harness has none of its own.
void keep_global_variables(ast::CompilationUnit& unit) {
    const auto keep = [&unit](std::vector<ast::DeclarationSection>& sections) {
        for (ast::DeclarationSection& section : sections) {
            if (auto* variables = std::get_if<ast::VarSection>(&section);
                variables && variables->kind == ast::VarSectionKind::Global) {
                unit.global_variable_lists.push_back(std::move(section));
            }
        }
    };
    for (ast::Configuration& configuration : unit.configurations) {
        keep(configuration.sections);
        for (ast::Resource& resource : configuration.resources) {
            keep(resource.sections);
        }
    }
}

} // namespace

void ignore_configurations(std::vector<ast::CompilationUnit>& units, const CompileOptions& options,
                           const SourceManager& sources, Diagnostics& diagnostics) {
    for (const FileId file : options.ignored_configurations) {
        const auto unit = std::ranges::find(units, file, &ast::CompilationUnit::file);
        if (unit != units.end()) {
            keep_global_variables(*unit);
            unit->configurations.clear();
        } else if (file < sources.file_count()) {
            diagnostics.error(DiagnosticCode::E0002, kOptionRange,
                              fmt::format("ignored_configurations: '{}' is not among the files "
                                          "compiled",
                                          sources.path(file)));
        } else {
            diagnostics.error(DiagnosticCode::E0002, kOptionRange,
                              fmt::format("ignored_configurations: file {} is not among the "
                                          "files compiled",
                                          file));
        }
    }
}

} // namespace eposp::compiler::options
