#include "eposp/compiler/compiler.hpp"

#include "codegen/program_generator.hpp"
#include "eposp/compiler/types/front_end.hpp"

namespace eposp::compiler {

std::optional<vm::Image> compile(SourceManager& sources, std::span<const FileId> files,
                                 Diagnostics& diagnostics) {
    const auto front_end = types::resolve_names(sources, files, diagnostics);
    if (diagnostics.has_errors()) {
        return std::nullopt;
    }
    codegen::ProgramGenerator generator({*front_end->model, front_end->units},
                                        {*front_end->library_model, front_end->library_units},
                                        diagnostics);
    return generator.generate();
}

} // namespace eposp::compiler
