#include "eposp/compiler/compiler.hpp"

#include "codegen/program_generator.hpp"
#include "eposp/compiler/types/front_end.hpp"

#include <vector>

namespace eposp::compiler {

std::optional<vm::Image> compile(SourceManager& sources, std::span<const FileId> files,
                                 Diagnostics& diagnostics, std::span<const FileId> libraries,
                                 const CompileOptions& options) {
    std::vector<FileId> all(files.begin(), files.end());
    all.insert(all.end(), libraries.begin(), libraries.end());
    const auto front_end = types::resolve_names(sources, all, diagnostics, options);
    if (diagnostics.has_errors()) {
        return std::nullopt;
    }
    codegen::ProgramGenerator generator({*front_end->model, front_end->units, libraries.size()},
                                        {*front_end->library_model, front_end->library_units},
                                        diagnostics, options);
    return generator.generate();
}

} // namespace eposp::compiler
