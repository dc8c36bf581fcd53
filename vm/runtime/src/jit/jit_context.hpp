#pragma once

#include "step_context.hpp"

#include <cstdint>

namespace eposp::vm::jit {

/// How compiled code left: the run is over, it reached a safe point with its slice used, or it
/// stopped with a run-time error.
enum class ExitKind : std::uint32_t { Finished, Suspended, Trapped };

/// Everything compiled code reads and writes outside VM memory, addressed from one register.
/// `step` comes first, so the context is also the StepContext handed to step functions.
struct JitContext {
    StepContext step;
    Activation* calls = nullptr; ///< the task's call stack
    std::uint32_t* depth = nullptr;
    std::uint64_t stack_end = 0;
    const void* const* entries = nullptr;       ///< machine address of each instruction
    const std::uint32_t* frame_sizes = nullptr; ///< per POU
    std::int64_t remaining = 0;                 ///< instructions left in the slice
    /// The machine stack pointer at entry: leaving from any call depth goes back to it.
    void* machine_stack = nullptr;
    ExitKind exit_kind = ExitKind::Finished;
    std::uint32_t exit_pc = 0;
    std::uint32_t exit_pou = 0;
    std::uint32_t exit_trap = 0;
};

} // namespace eposp::vm::jit
