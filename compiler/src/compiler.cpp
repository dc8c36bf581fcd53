#include "eposp/compiler/compiler.hpp"

#include "checks/checks.hpp"
#include "codegen/program_generator.hpp"
#include "eposp/compiler/types/front_end.hpp"
#include "lower/image_passes.hpp"

#include <memory>
#include <vector>

namespace eposp::compiler {
namespace {

struct Checked {
    std::unique_ptr<types::FrontEnd> front_end;
    std::unique_ptr<types::TypedProgram> program;
};

// Parse, names, types and checks: the stages that find the program's errors. Syntax and name
// errors stop before typing; typing and the checks then both run, so that the errors come in one
// compilation.
std::optional<Checked> check_stages(SourceManager& sources, std::span<const FileId> files,
                                    Diagnostics& diagnostics, std::span<const FileId> libraries,
                                    const CompileOptions& options) {
    std::vector<FileId> all(files.begin(), files.end());
    all.insert(all.end(), libraries.begin(), libraries.end());
    auto front_end = types::resolve_names(sources, all, diagnostics, options);
    if (diagnostics.has_errors()) {
        return std::nullopt;
    }
    auto program = types::type_program(
        front_end->units, *front_end->model,
        [&front_end = *front_end](std::string_view name) { return front_end.library_pou(name); },
        diagnostics);
    checks::check_program(*program, front_end->units, libraries.size(), options, diagnostics);
    return Checked{std::move(front_end), std::move(program)};
}

} // namespace

bool check(SourceManager& sources, std::span<const FileId> files, Diagnostics& diagnostics,
           std::span<const FileId> libraries, const CompileOptions& options) {
    check_stages(sources, files, diagnostics, libraries, options);
    return !diagnostics.has_errors();
}

std::optional<vm::Image> compile(SourceManager& sources, std::span<const FileId> files,
                                 Diagnostics& diagnostics, std::span<const FileId> libraries,
                                 const CompileOptions& options) {
    // Code generation runs on a program without errors: it reports only the limits of the image
    // (E05xx).
    const auto checked = check_stages(sources, files, diagnostics, libraries, options);
    if (!checked || diagnostics.has_errors()) {
        return std::nullopt;
    }
    const types::FrontEnd& front_end = *checked->front_end;
    // The library's POUs are generated like the program's: typed first, checked never (they
    // are the project's own code).
    types::type_library(*checked->program, front_end.library_units, *front_end.library_model,
                        diagnostics);
    if (diagnostics.has_errors()) {
        return std::nullopt;
    }
    codegen::ProgramGenerator generator({*front_end.model, front_end.units, libraries.size()},
                                        {*front_end.library_model, front_end.library_units},
                                        *checked->program, diagnostics, options);
    auto image = generator.generate();
    if (image) {
        lower::optimise_image(*image);
    }
    return image;
}

} // namespace eposp::compiler
