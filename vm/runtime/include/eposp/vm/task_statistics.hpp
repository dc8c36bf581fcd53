#pragma once

#include "eposp/core/time.hpp"

#include <cstdint>

namespace eposp::vm {

/// What a task did since the program started: the figures `eposp run` prints and a service tool
/// would show. Times are virtual: execution time is the instructions of a cycle through the
/// runtime's cost model (time spent preempted is not counted), jitter how late a cycle started
/// against its due time.
struct TaskStatistics {
    std::uint64_t cycles = 0;   ///< completed cycles (a faulted one does not count)
    std::uint64_t overruns = 0; ///< activations lost because the task was still busy
    std::uint64_t instructions_last = 0;
    core::Duration execution_last{};
    core::Duration execution_min{};
    core::Duration execution_max{};
    core::Duration execution_total{};
    core::Duration jitter_last{};
    core::Duration jitter_max{};

    core::Duration execution_average() const;
    /// A completed cycle.
    void record_cycle(std::uint64_t instructions, core::Duration execution, core::Duration jitter);
};

} // namespace eposp::vm
