#include "compile_option_passes.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::compiler::options {

void ignore_configurations(std::vector<ast::CompilationUnit>& units, const CompileOptions& options,
                           const SourceManager& sources, Diagnostics& diagnostics) {
    for (const FileId file : options.ignored_configurations) {
        const auto unit = std::ranges::find(units, file, &ast::CompilationUnit::file);
        if (unit != units.end()) {
            unit->configurations.clear();
        } else if (file < sources.file_count()) {
            diagnostics.error(kOptionRange,
                              fmt::format("ignored_configurations: '{}' is not among the files "
                                          "compiled",
                                          sources.path(file)));
        } else {
            diagnostics.error(kOptionRange,
                              fmt::format("ignored_configurations: file {} is not among the "
                                          "files compiled",
                                          file));
        }
    }
}

} // namespace eposp::compiler::options
