#pragma once

#include "jit_context.hpp"

#include <cstddef>

// Where compiled code finds the fields of the JitContext, from r15.

namespace eposp::vm::jit {

constexpr int context_base(Base base) {
    return static_cast<int>(offsetof(JitContext, step) + offsetof(StepContext, base) +
                            sizeof(std::uint8_t*) * static_cast<int>(base));
}
inline constexpr int kRemaining = offsetof(JitContext, remaining);
inline constexpr int kMachineStack = offsetof(JitContext, machine_stack);
inline constexpr int kCalls = offsetof(JitContext, calls);
inline constexpr int kDepth = offsetof(JitContext, depth);
inline constexpr int kStackEnd = offsetof(JitContext, stack_end);
inline constexpr int kEntries = offsetof(JitContext, entries);
inline constexpr int kFrameSizes = offsetof(JitContext, frame_sizes);
inline constexpr int kMemSize = offsetof(JitContext, step) + offsetof(StepContext, mem_size);
inline constexpr int kExitKind = offsetof(JitContext, exit_kind);
inline constexpr int kExitPc = offsetof(JitContext, exit_pc);
inline constexpr int kExitPou = offsetof(JitContext, exit_pou);
inline constexpr int kExitTrap = offsetof(JitContext, exit_trap);
// emit_calls.cpp writes an Activation as four 32-bit words.
static_assert(sizeof(Activation) == 16);

} // namespace eposp::vm::jit
