#pragma once

#include "eposp/compiler/compiler.hpp"

#include <optional>
#include <span>

namespace eposp::device {

/// Compiles the files of one program for the EPOS P: with the motion library linked, so that a
/// program uses AXIS_REF and the MC_* blocks without declaring them (plcopen::MotionLibrary),
/// and with the device's events for the TASKs that name one.
std::optional<vm::Image> compile_program(compiler::SourceManager& sources,
                                         std::span<const compiler::FileId> files,
                                         compiler::Diagnostics& diagnostics);

/// What `eposp check` runs: compile_program's stages up to the checks (compiler::check), without
/// code generation. True when there is no error.
bool check_program(compiler::SourceManager& sources, std::span<const compiler::FileId> files,
                   compiler::Diagnostics& diagnostics);

} // namespace eposp::device
