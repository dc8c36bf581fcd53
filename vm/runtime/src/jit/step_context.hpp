#pragma once

#include "eposp/vm/image.hpp"
#include "eposp/vm/instruction.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/task_state.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace eposp::vm::jit {

/// What a step function reads besides its instruction. Compiled code keeps `base` current across
/// calls and returns, so a step function resolves operands exactly as the interpreter does.
struct StepContext {
    std::uint8_t* base[4] = {}; ///< indexed by Base
    std::uint8_t* mem = nullptr;
    std::uint64_t mem_size = 0;
    const ArrayDescriptor* arrays = nullptr;
    const Program* program = nullptr;
    TaskState* task = nullptr;         ///< the running task (native calls: failure, call site)
    const Instruction* code = nullptr; ///< the instructions step functions are handed
};

/// A step function's outcome: go on, take the instruction's branch, or stop with trap
/// `result - kStepTrap`.
inline constexpr std::uint32_t kStepNext = 0;
inline constexpr std::uint32_t kStepTaken = 1;
inline constexpr std::uint32_t kStepTrap = 2;

/// Executes one instruction of a family that does not change the activation.
using StepFunction = std::uint32_t (*)(StepContext& context, const Instruction& instruction);

/// The step function of `op`, or nullptr for the families compiled code does itself: jumps,
/// jump tables, calls and returns.
StepFunction step_function(Opcode op);

} // namespace eposp::vm::jit
