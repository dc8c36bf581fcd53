#pragma once

#include "eposp/vm/image_limits.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace eposp::vm {

/// Why a task was stopped by the interpreter.
enum class Trap : std::uint8_t {
    DivisionByZero,
    IndexOutOfRange,
    NullDereference,
    InvalidAddress,
    BudgetExceeded,
    StackOverflow,
    NativeError,
    SubrangeViolation, ///< a value stored into a subrange type lies outside it
};

std::string_view trap_name(Trap trap);

/// Where a task stopped with a run-time error.
struct Fault {
    Trap trap = Trap::DivisionByZero;
    std::uint32_t pou = 0;
    std::uint32_t instruction = 0;
    std::uint32_t line = 0;    ///< 0 when the POU has no line table
    std::string native_reason; ///< for NativeError
};

/// One activation: where it runs and which memory it works on (offsets into VM memory).
struct Activation {
    std::uint32_t pc = 0;
    std::uint32_t pou = 0;
    std::uint32_t frame = 0;
    std::uint32_t self = 0;
};

enum class RunState : std::uint8_t { Idle, Suspended, Finished, Faulted };

inline constexpr std::uint64_t kUnlimited = std::numeric_limits<std::uint64_t>::max();

/// Everything the interpreter needs to continue a task later: suspending at a safe point saves
/// the current activation here and resuming picks it up, so a higher-priority task can run in
/// between on its own stack.
struct TaskState {
    std::uint32_t stack_begin = 0; ///< this task's frames live in [stack_begin, stack_end)
    std::uint32_t stack_end = 0;
    RunState state = RunState::Idle;
    Activation current;
    std::vector<Activation> calls = std::vector<Activation>(kMaxCallDepth);
    std::uint32_t depth = 0;
    /// Watchdog: instructions one run of the task may execute.
    std::uint64_t budget = kUnlimited;
    /// Instructions executed since the run started (counted at safe points and at the end).
    std::uint64_t executed = 0;
    Fault fault;
};

} // namespace eposp::vm
