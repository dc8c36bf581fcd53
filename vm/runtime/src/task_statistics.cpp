#include "eposp/vm/task_statistics.hpp"

#include <algorithm>

namespace eposp::vm {

core::Duration TaskStatistics::execution_average() const {
    return cycles == 0 ? core::Duration::zero()
                       : execution_total / static_cast<core::Duration::rep>(cycles);
}

void TaskStatistics::record_cycle(std::uint64_t instructions, core::Duration execution,
                                  core::Duration jitter) {
    execution_min = cycles == 0 ? execution : std::min(execution_min, execution);
    execution_max = std::max(execution_max, execution);
    execution_total += execution;
    execution_last = execution;
    instructions_last = instructions;
    jitter_last = jitter;
    jitter_max = std::max(jitter_max, jitter);
    ++cycles;
}

} // namespace eposp::vm
