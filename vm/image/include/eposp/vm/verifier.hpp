#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"
#include "eposp/vm/image_limits.hpp"

#include <optional>

namespace eposp::vm {

/// Checks everything the interpreter relies on, so that it can run without checking static
/// operands: every memory operand lies inside its area for its width (static data, the POU's
/// frame, its instance, its out area), every jump stays inside its POU, every POU ends in a
/// jump or return (no running off its end), call and import indices exist and call the right
/// kind of POU, tasks fit their stacks, and the tables (types, symbols, bindings, retain) stay
/// inside static data. Returns the first defect found, or nothing.
std::optional<core::Error> verify(const Image& image);

} // namespace eposp::vm
