#include "eposp/vm/task_dispatcher.hpp"

#include "eposp/vm/runtime_error.hpp"

#include <algorithm>
#include <tuple>

namespace eposp::vm {
namespace {

/// align() leaves a task alone within 1/8 of the clock's period of its grid.
constexpr int kAlignmentTolerance = 8;

} // namespace

TaskDispatcher::TaskDispatcher(core::EventLoop& loop, Machine& machine, TaskHooks& hooks,
                               CostModel cost)
    : loop_(loop), machine_(machine), hooks_(hooks), cost_(cost) {
    for (const Task& task : machine.program().image().tasks) {
        Slot slot;
        slot.spec = &task;
        slots_.push_back(slot);
    }
}

bool TaskDispatcher::releases_cyclically(const Slot& slot) const {
    // A cyclic task without an interval would be due all the time: it is never released.
    return slot.spec->kind == TaskKind::Cyclic && slot.spec->interval_ns > 0 && !slot.faulted;
}

void TaskDispatcher::start() {
    stop();
    running_ = true;
    for (Slot& slot : slots_) {
        // A new run: everything but the task and its watchdog starts afresh.
        slot = Slot{.spec = slot.spec, .watchdog = slot.watchdog, .statistics = {}};
        slot.next_release = loop_.now();
    }
    release_on_rising_edges();
    dispatch();
}

void TaskDispatcher::stop() {
    running_ = false;
    slice_in_flight_ = false;
    wake_up_.cancel();
    slice_end_.cancel();
    for (Slot& slot : slots_) {
        slot.active = slot.started = false;
    }
}

void TaskDispatcher::raise_event(std::size_t task) {
    if (!running_ || slots_.at(task).faulted) {
        return;
    }
    release(task, loop_.now(), error_code::kInterruptTask);
    dispatch();
}

void TaskDispatcher::check_event_inputs() {
    release_on_rising_edges();
    dispatch();
}

void TaskDispatcher::release_on_rising_edges() {
    const auto memory = machine_.memory();
    for (std::size_t task = 0; task < slots_.size(); ++task) {
        Slot& slot = slots_[task];
        if (!slot.spec->event_offset || slot.faulted) {
            continue;
        }
        // IEC 61131-3 6.8.2: SINGLE fires on the rising edge; before the start it counts as
        // FALSE, so a variable initialised TRUE releases the task once at the start.
        const bool level = memory[*slot.spec->event_offset] != 0;
        if (level && !slot.event_level && running_) {
            release(task, loop_.now(), error_code::kInterruptTask);
        }
        slot.event_level = level;
    }
}

void TaskDispatcher::align(core::TimePoint anchor, core::Duration period) {
    if (!running_ || period <= core::Duration::zero()) {
        return;
    }
    const core::TimePoint now = loop_.now();
    bool moved = false;
    for (Slot& slot : slots_) {
        const core::Duration interval(slot.spec->interval_ns);
        if (!releases_cyclically(slot) || interval % period != core::Duration::zero()) {
            continue;
        }
        // In step already (a task of several periods keeps its phase), or near enough: in real
        // time the clock's ticks are seen a little late, and chasing that jitter would move the
        // task at every tick.
        core::Duration phase = (slot.next_release - anchor) % period;
        if (phase < core::Duration::zero()) {
            phase += period;
        }
        if (std::min(phase, period - phase) <= period / kAlignmentTolerance) {
            continue;
        }
        // The first tick of the grid at or after now (the anchor may lie either side of it).
        core::Duration offset = (anchor - now) % period;
        if (offset < core::Duration::zero()) {
            offset += period;
        }
        slot.next_release = now + offset;
        moved = true;
    }
    if (moved) {
        arm_wake_up();
    }
}

void TaskDispatcher::set_watchdog(std::size_t task, std::uint64_t instructions) {
    slots_.at(task).watchdog = instructions;
}

void TaskDispatcher::release(std::size_t task, core::TimePoint due, std::uint16_t overrun_code) {
    Slot& slot = slots_[task];
    if (slot.active) {
        ++slot.statistics.overruns;
        hooks_.on_overrun(task, overrun_code);
        return;
    }
    slot.active = true;
    slot.due = due;
}

void TaskDispatcher::release_due_tasks() {
    const core::TimePoint now = loop_.now();
    for (std::size_t task = 0; task < slots_.size(); ++task) {
        Slot& slot = slots_[task];
        if (!releases_cyclically(slot)) {
            continue;
        }
        const core::Duration interval(slot.spec->interval_ns);
        while (slot.next_release <= now && !slot.faulted) {
            release(task, slot.next_release, error_code::kTimerTask);
            slot.next_release += interval;
        }
    }
}

std::optional<std::size_t> TaskDispatcher::next_to_run() const {
    std::optional<std::size_t> best;
    const auto rank = [this](std::size_t task) {
        return std::tuple(slots_[task].spec->priority, !slots_[task].started, task);
    };
    for (std::size_t task = 0; task < slots_.size(); ++task) {
        if (slots_[task].active && !slots_[task].faulted && (!best || rank(task) < rank(*best))) {
            best = task;
        }
    }
    return best;
}

std::uint64_t TaskDispatcher::slice_for(std::size_t task) const {
    std::uint64_t slice = cost_.quantum;
    if (cost_.ns_per_instruction == 0) {
        return slice; // no time passes while it runs: nothing can be released meanwhile
    }
    const core::TimePoint now = loop_.now();
    for (const Slot& other : slots_) {
        if (releases_cyclically(other) && other.spec->priority < slots_[task].spec->priority) {
            const auto until = static_cast<std::uint64_t>((other.next_release - now).count());
            // Instructions until the release (at least one: a slice ends at a safe point).
            slice =
                std::min(slice, std::max<std::uint64_t>(1, (until + cost_.ns_per_instruction - 1) /
                                                               cost_.ns_per_instruction));
        }
    }
    return slice;
}

void TaskDispatcher::begin_cycle(std::size_t task) {
    Slot& slot = slots_[task];
    slot.started = true;
    slot.started_at = loop_.now();
    slot.entry = 0;
    slot.executed = 0;
    hooks_.before_cycle(task);
    if (!slot.spec->entries.empty()) {
        begin_entry(task);
    }
}

void TaskDispatcher::begin_entry(std::size_t task) {
    Slot& slot = slots_[task];
    // The watchdog covers the whole cycle: each program gets what the previous ones left.
    machine_.set_budget(task, slot.watchdog > slot.executed ? slot.watchdog - slot.executed : 0);
    machine_.start(task, slot.entry);
}

TaskDispatcher::Outcome TaskDispatcher::run_slice(std::size_t task, std::uint64_t slice,
                                                  std::uint64_t& executed) {
    Slot& slot = slots_[task];
    executed = 0;
    while (slot.entry < slot.spec->entries.size()) {
        const std::uint64_t before = machine_.task(task).executed;
        const RunState state = machine_.run(task, slice - executed);
        const std::uint64_t ran = machine_.task(task).executed - before;
        executed += ran;
        slot.executed += ran;
        if (state == RunState::Faulted) {
            return Outcome::Faulted;
        }
        if (state != RunState::Finished) {
            return Outcome::Suspended;
        }
        if (++slot.entry == slot.spec->entries.size()) {
            break;
        }
        begin_entry(task);
        if (executed >= slice) {
            return Outcome::Suspended;
        }
    }
    return Outcome::Finished;
}

void TaskDispatcher::end_slice(std::size_t task, Outcome outcome) {
    Slot& slot = slots_[task];
    switch (outcome) {
    case Outcome::Suspended:
        return;
    case Outcome::Finished:
        slot.active = slot.started = false;
        slot.statistics.record_cycle(slot.executed, cost_of(slot.executed),
                                     slot.started_at - slot.due);
        hooks_.after_cycle(task);
        release_on_rising_edges();
        return;
    case Outcome::Faulted:
        slot.active = slot.started = false;
        slot.faulted = true;
        hooks_.on_fault(task);
        return;
    }
}

void TaskDispatcher::dispatch() {
    if (dispatching_) {
        return; // the running dispatch picks up what was released
    }
    if (slice_in_flight_) {
        // The CPU is busy: releases happen on time (an overrun is reported when it occurs) and
        // run when the slice ends.
        release_due_tasks();
        arm_wake_up();
        return;
    }
    dispatching_ = true;
    while (running_) {
        release_due_tasks();
        const auto task = next_to_run();
        if (!task) {
            arm_wake_up();
            break;
        }
        if (!slots_[*task].started) {
            begin_cycle(*task);
        }
        std::uint64_t executed = 0;
        const Outcome outcome = run_slice(*task, slice_for(*task), executed);
        const core::Duration cost = cost_of(executed);
        if (cost == core::Duration::zero()) {
            end_slice(*task, outcome);
            continue;
        }
        arm_wake_up();
        // The CPU is busy with these instructions until now + cost; what they complete (the
        // outputs of a finished cycle) happens then.
        slice_in_flight_ = true;
        slice_end_ = core::ScopedTimer(loop_, loop_.after(cost, [this, task = *task, outcome] {
            slice_in_flight_ = false;
            end_slice(task, outcome);
            dispatch();
        }));
        break;
    }
    dispatching_ = false;
}

void TaskDispatcher::arm_wake_up() {
    std::optional<core::TimePoint> next;
    for (const Slot& slot : slots_) {
        if (releases_cyclically(slot) && (!next || slot.next_release < *next)) {
            next = slot.next_release;
        }
    }
    if (next) {
        wake_up_ = core::ScopedTimer(loop_, loop_.at(*next, [this] { dispatch(); }));
    } else {
        wake_up_.cancel();
    }
}

core::Duration TaskDispatcher::cost_of(std::uint64_t instructions) const {
    return core::Duration(
        static_cast<core::Duration::rep>(instructions * cost_.ns_per_instruction));
}

} // namespace eposp::vm
