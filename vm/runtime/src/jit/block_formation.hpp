#pragma once

#include "eposp/vm/image.hpp"

#include <vector>

// What the translator treats as a unit: basic blocks. Instructions are charged per block (its
// length where it ends, the part run where it traps) and a register is trusted to hold a stored
// value only inside one block.

namespace eposp::vm::jit {

/// Whether control may go elsewhere after `ins`: a branch, a jump table, a call or return (the
/// families without a step function), and a native call, which is a safe point.
bool ends_block(const Instruction& ins);

/// Where basic blocks start, indexed by instruction (one past the end included): POU entries,
/// jump and jump-table targets, and what follows a block's end.
std::vector<bool> block_starts(const Image& image);

} // namespace eposp::vm::jit
