#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace eposp::device::cli {

/// How a command prints the compiler's diagnostics: as a compiler does (stderr), or as JSON, one
/// object a line on stdout (compiler/diagnostics_json.hpp; docs/diagnostics.md) for editors and
/// CI.
enum class ErrorFormat { Human, Json };

/// Adds `--error-format human|json`.
void add_error_format_option(CLI::App& command, ErrorFormat& format);

/// Compiles the `.st` files of one program, printing their diagnostics (warnings too) to stderr
/// like a compiler; the error says why there is no image.
core::Result<vm::Image> compile_sources(const std::vector<std::string>& paths,
                                        ErrorFormat format = ErrorFormat::Human);

/// Checks the `.st` files of one program as `eposp check` does: the compiler's stages up to the
/// checks, without code generation (device::check_program), printing the diagnostics as
/// compile_sources does; the error says that there are errors.
core::Result<bool> check_sources(const std::vector<std::string>& paths,
                                 ErrorFormat format = ErrorFormat::Human);

/// The program a command works on, from its FILES: one `.epx` image as `eposp build` writes it,
/// or the `.st` files of one program, compiled (their diagnostics printed to stderr like
/// `eposp check`). The error says why there is no image.
core::Result<vm::Image> program_image(const std::vector<std::string>& paths,
                                      ErrorFormat format = ErrorFormat::Human);

} // namespace eposp::device::cli
