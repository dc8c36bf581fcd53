#pragma once

#include "eposp/vm/image.hpp"

#include <string>

namespace eposp::vm {

/// The whole image as text for `eposp dump`: sizes, tasks, POUs, symbols, I/O bindings,
/// retain ranges, imports, then each POU's code with operands by name and source lines.
/// Works on unverified images too (out-of-range references print as such), so a rejected
/// image can still be inspected.
std::string disassemble(const Image& image);

/// One instruction, e.g. `AddI32 f+0, f+0, #1`.
std::string disassemble(const Image& image, const Instruction& instruction);

} // namespace eposp::vm
