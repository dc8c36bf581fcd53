#pragma once

#include "eposp/compiler/compile_options.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/source_manager.hpp"
#include "eposp/vm/image.hpp"

#include <optional>
#include <span>

namespace eposp::compiler {

/// Parses, resolves, type-checks and generates the program image of the files of one program.
/// Diagnostics (errors and warnings) go to `diagnostics`; nullopt when there are errors.
///
/// The image imports the natives of vm::stdlib::register_standard_library and, when the program
/// uses a timer or RTC, vm::stdlib::clock_binding (vm::stdlib::register_clock). Symbols: a
/// configuration global as `Config0.name`, a global variable list's variable by its name alone
/// (`name`), a program instance as its instance name (`Inst0`, or the program's name when there
/// is no configuration) with its variables below it (`Inst0.x`). A program without a configuration
/// runs in a cyclic task of 10 ms.
///
/// `libraries` are files of declarations the host links with every program (plcopen's motion
/// blocks): their types and POUs are visible like the program's own, their POUs are generated
/// only when called, and a FUNCTION_BLOCK without statements in them is a native block whose
/// body the host registers in C++ (docs/runtime.md, "Native function blocks").
///
/// `options` depart from the files as written (ignored CONFIGURATIONs, FB test doubles:
/// compile_options.hpp); an option that names no file or FUNCTION_BLOCK is an error.
std::optional<vm::Image> compile(SourceManager& sources, std::span<const FileId> files,
                                 Diagnostics& diagnostics, std::span<const FileId> libraries = {},
                                 const CompileOptions& options = {});

/// The stages of compile() that find the program's errors, and not code generation: parse,
/// names, types and checks (what `eposp check` runs). Their diagnostics go to `diagnostics`;
/// true when there is no error. A limit that only code generation meets (E0502: data larger
/// than an image holds) is left to compile().
bool check(SourceManager& sources, std::span<const FileId> files, Diagnostics& diagnostics,
           std::span<const FileId> libraries = {}, const CompileOptions& options = {});

} // namespace eposp::compiler
