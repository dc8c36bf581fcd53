#pragma once

// What the reference evaluator models, checked before it runs anything, so that a program
// using anything else is refused up front (errors()) rather than half run.

#include "eposp/compiler/types/front_end.hpp"

namespace eposp::reference {

/// Throws Unsupported naming the first construct of the program the evaluator does not model.
void check_supported(const compiler::types::FrontEnd& front_end);

} // namespace eposp::reference
