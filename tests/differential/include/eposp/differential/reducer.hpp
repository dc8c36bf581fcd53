#pragma once

// A small delta-debugging reducer for generated programs: drops statements (declarations
// included), replaces a compound statement by one of its blocks and an expression by a literal
// of its type, one at a time, keeping each
// change under which the program stays interesting (it still compiles and the executors still
// disagree the same way), until no single change is kept.

#include "eposp/differential/program_tree.hpp"

#include <functional>
#include <string>

namespace eposp::differential {

/// Whether a candidate program (its ST source) still shows what is being reduced.
using Interesting = std::function<bool(const std::string& source)>;

/// The smallest program reached from `program` by changes under which `interesting` held.
Block reduce(Block program, const Interesting& interesting);

} // namespace eposp::differential
