#pragma once

#include "coverage_counters.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/task_state.hpp"

#include <span>

namespace eposp::vm::detail {

/// Runs `task` from its saved activation until it returns, faults, or reaches the first safe
/// point (a taken jump or a call) after `slice` instructions. With `coverage`, counts what it
/// executes there.
RunState execute(const Program& program, std::span<std::uint8_t> memory, TaskState& task,
                 std::uint64_t slice, CoverageCounters* coverage = nullptr);

} // namespace eposp::vm::detail
