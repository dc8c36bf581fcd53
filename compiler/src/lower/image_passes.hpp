#pragma once

// The lowering passes over the emitted code, in the order the compiler runs them
// (docs/architecture.md, "The compiler"): each is a pass of its own file that takes a verified
// image and leaves one that does the same, faster.

#include "eposp/vm/image.hpp"

namespace eposp::compiler::lower {

/// Jump threading (jump_threading.hpp), back-edge duplication (back_edge_duplication.hpp), leaf
/// call inlining (call_inlining.hpp), then jump threading again over the inlined bodies.
void optimise_image(vm::Image& image);

} // namespace eposp::compiler::lower
