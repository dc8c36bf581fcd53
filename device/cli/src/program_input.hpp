#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <string>
#include <vector>

namespace eposp::device::cli {

/// Compiles the `.st` files of one program, printing their diagnostics (warnings too) to stderr
/// like a compiler; the error says why there is no image.
core::Result<vm::Image> compile_sources(const std::vector<std::string>& paths);

/// The program a command works on, from its FILES: one `.epx` image as `eposp build` writes it,
/// or the `.st` files of one program, compiled (their diagnostics printed to stderr like
/// `eposp check`). The error says why there is no image.
core::Result<vm::Image> program_image(const std::vector<std::string>& paths);

} // namespace eposp::device::cli
