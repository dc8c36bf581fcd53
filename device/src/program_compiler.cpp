#include "eposp/device/program_compiler.hpp"

#include "eposp/plcopen/motion_library.hpp"

namespace eposp::device {

std::optional<vm::Image> compile_program(compiler::SourceManager& sources,
                                         std::span<const compiler::FileId> files,
                                         compiler::Diagnostics& diagnostics) {
    const compiler::FileId motion =
        sources.add("<motion library>", plcopen::MotionLibrary::source());
    return compiler::compile(sources, files, diagnostics, std::span(&motion, 1));
}

} // namespace eposp::device
