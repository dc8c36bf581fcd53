#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/vm/machine.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace eposp::vm {

/// Runs a program's cyclic tasks on the event loop as the configuration declares them (IEC
/// 61131-3 ed. 3, 6.8.2): each task every INTERVAL from start(), and where several are due at
/// the same instant, the higher PRIORITY (smaller number) first and equal priorities in the
/// order of the task table. The n-th cycle of a task is due at start + n * INTERVAL, computed
/// from the schedule, so a task never drifts. A task that faults stops; the others go on.
///
/// Preemption, event (SINGLE) tasks, overrun detection and the process image belong to the PLC
/// runtime that builds on this.
class TaskScheduler {
public:
    /// Called once for a task that stopped with a run-time error (Machine::describe_fault).
    using FaultHandler = std::function<void(std::size_t task)>;

    TaskScheduler(core::EventLoop& loop, Machine& machine);

    void on_fault(FaultHandler handler) { on_fault_ = std::move(handler); }
    /// Runs the first cycle of every cyclic task now and the next ones at their intervals.
    void start();
    void stop();

    /// Cycles the task has completed (a faulted cycle does not count).
    std::uint64_t cycles(std::size_t task) const { return tasks_.at(task).cycles; }
    bool faulted(std::size_t task) const { return tasks_.at(task).faulted; }

private:
    struct Schedule {
        std::size_t task = 0;
        core::Duration interval{};
        core::TimePoint next_due{};
        std::uint64_t cycles = 0;
        bool faulted = false;
    };

    void run_due_tasks();
    void arm_next();

    core::EventLoop& loop_;
    Machine& machine_;
    std::vector<Schedule> tasks_;    ///< indexed by task
    std::vector<std::size_t> order_; ///< cyclic tasks by priority, then table order
    core::ScopedTimer timer_;
    FaultHandler on_fault_;
};

} // namespace eposp::vm
