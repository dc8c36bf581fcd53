#pragma once

#include "eposp/vm/image.hpp"
#include "eposp/vm/task_state.hpp"

#include <cstdint>

// How a run of a task begins and ends, the same for both engines: how many instructions it may
// execute, and what the task records when it finishes, reaches a safe point with its slice
// used, or stops with a run-time error.

namespace eposp::vm::detail {

/// Starts a run: forgets the last native failure and returns the instructions the run may
/// execute (the slice, bounded by what is left of the budget).
std::uint64_t begin_run(TaskState& task, std::uint64_t slice);

/// The base pointers (indexed by Base) of activation `at`, whose POU has `frame_size` bytes of
/// frame: its out area follows them.
void activation_bases(std::uint8_t* (&base)[4], std::uint8_t* mem, const Activation& at,
                      std::uint32_t frame_size);

/// `executed` is what the run executed in each case.
RunState end_finished(TaskState& task, std::uint64_t executed);
/// Suspended at `at`, or faulted with BudgetExceeded if that used up the budget.
RunState end_suspended(TaskState& task, const Image& image, std::uint64_t executed,
                       const Activation& at);
RunState end_faulted(TaskState& task, const Image& image, std::uint64_t executed, Trap trap,
                     std::uint32_t pou, std::uint32_t instruction);

} // namespace eposp::vm::detail
