#pragma once

#include "eposp/vm/image.hpp"

namespace eposp::compiler::lower {

/// A `Jmp` to a FOR back-edge becomes a copy of the back-edge followed by a jump to the loop's
/// exit: a branch of an IF or CASE inside a FOR loop then loops with one instruction instead of
/// two, and the extra jump runs only once, when the loop ends.
void duplicate_back_edges(vm::Image& image);

} // namespace eposp::compiler::lower
