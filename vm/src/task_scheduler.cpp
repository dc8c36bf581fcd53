#include "eposp/vm/task_scheduler.hpp"

#include <algorithm>
#include <optional>

namespace eposp::vm {

TaskScheduler::TaskScheduler(core::EventLoop& loop, Machine& machine)
    : loop_(loop), machine_(machine) {
    const auto& tasks = machine.program().image().tasks;
    for (std::size_t task = 0; task < tasks.size(); ++task) {
        tasks_.push_back({.task = task, .interval = core::Duration(tasks[task].interval_ns)});
        if (tasks[task].kind == TaskKind::Cyclic && tasks[task].interval_ns > 0) {
            order_.push_back(task);
        }
    }
    std::stable_sort(order_.begin(), order_.end(), [&tasks](std::size_t a, std::size_t b) {
        return tasks[a].priority < tasks[b].priority;
    });
}

void TaskScheduler::start() {
    for (const std::size_t task : order_) {
        tasks_[task].next_due = loop_.now();
    }
    run_due_tasks();
}

void TaskScheduler::stop() {
    timer_.cancel();
}

void TaskScheduler::run_due_tasks() {
    const core::TimePoint now = loop_.now();
    for (const std::size_t task : order_) {
        Schedule& schedule = tasks_[task];
        if (schedule.faulted || schedule.next_due > now) {
            continue;
        }
        schedule.next_due += schedule.interval;
        if (machine_.run_cycle(task) == RunState::Faulted) {
            schedule.faulted = true;
            if (on_fault_) {
                on_fault_(task);
            }
            continue;
        }
        ++schedule.cycles;
    }
    arm_next();
}

void TaskScheduler::arm_next() {
    std::optional<core::TimePoint> next;
    for (const std::size_t task : order_) {
        if (!tasks_[task].faulted && (!next || tasks_[task].next_due < *next)) {
            next = tasks_[task].next_due;
        }
    }
    if (next) {
        timer_ = core::ScopedTimer(loop_, loop_.at(*next, [this] { run_due_tasks(); }));
    }
}

} // namespace eposp::vm
