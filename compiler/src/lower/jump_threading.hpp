#pragma once

#include "eposp/vm/image.hpp"

namespace eposp::compiler::lower {

/// A peephole pass over finished code: every jump (also conditional and FOR back-edges) to a
/// `Jmp` goes straight to the final target, and a `Jmp` to a `Ret` becomes a `Ret`. (A FOR
/// back-edge cannot be copied: its fall-through is the loop's exit.) The number and order of
/// instructions do not change, so line tables stay valid.
void thread_jumps(vm::Image& image);

} // namespace eposp::compiler::lower
