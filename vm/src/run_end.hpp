#pragma once

#include "eposp/vm/image.hpp"
#include "eposp/vm/task_state.hpp"

#include <cstdint>

// How a run of a task begins and ends, the same for both engines: how many instructions it may
// execute, and what the task records when it finishes, reaches a safe point with its slice
// used, or stops with a run-time error.

namespace eposp::vm::detail {

/// The instructions a run may execute: the slice, bounded by what is left of the budget.
std::uint64_t run_limit(const TaskState& task, std::uint64_t slice);

/// `executed` is what the run executed in each case.
RunState end_finished(TaskState& task, std::uint64_t executed);
/// Suspended at `at`, or faulted with BudgetExceeded if that used up the budget.
RunState end_suspended(TaskState& task, const Image& image, std::uint64_t executed,
                       const Activation& at);
RunState end_faulted(TaskState& task, const Image& image, std::uint64_t executed, Trap trap,
                     std::uint32_t pou, std::uint32_t instruction);

} // namespace eposp::vm::detail
