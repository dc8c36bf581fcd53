#pragma once

#include "eposp/vm/image.hpp"

namespace eposp::compiler::lower {

/// Puts the body of every small leaf function or FB in place of its calls (`Call`, and
/// `CallFb` on a directly addressed instance): PLC code calls many small FBs (R_TRIG, CTU, SR,
/// TON) once per scan, and the call and return cost as much as their bodies. The callee's frame
/// becomes the caller's out area (where a call would have put it), its instance operands point
/// into the caller's instance, and each POU records the copies so that run-time errors still
/// name the callee and its line. The callees stay in the image for the calls not inlined.
void inline_leaf_calls(vm::Image& image);

} // namespace eposp::compiler::lower
