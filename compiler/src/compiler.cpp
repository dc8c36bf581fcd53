#include "eposp/compiler/compiler.hpp"

#include "checks/checks.hpp"
#include "codegen/program_generator.hpp"
#include "eposp/compiler/types/front_end.hpp"
#include "lower/image_passes.hpp"

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
    // Code generation still reports the type errors itself (issue 17): the typing stage's
    // go aside, and the checks run on what it typed.
    Diagnostics typing;
    const auto program = types::type_program(
        front_end->units, *front_end->model,
        [&front_end](std::string_view name) { return front_end->library_pou(name); }, typing);
    checks::check_program(*program, front_end->units, libraries.size(), options, diagnostics);
    codegen::ProgramGenerator generator({*front_end->model, front_end->units, libraries.size()},
                                        {*front_end->library_model, front_end->library_units},
                                        diagnostics, options);
    auto image = generator.generate();
    if (image) {
        lower::optimise_image(*image);
    }
    return image;
}

} // namespace eposp::compiler
