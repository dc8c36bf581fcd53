#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/task_statistics.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace eposp::vm {

/// What the runtime does around the cycles the dispatcher runs.
class TaskHooks {
public:
    virtual ~TaskHooks() = default;
    /// Before the first instruction of a cycle (inputs in, forced values applied).
    virtual void before_cycle(std::size_t task) = 0;
    /// After the last instruction of a cycle, at its virtual end time (outputs out).
    virtual void after_cycle(std::size_t task) = 0;
    /// The task stopped with a run-time error (Machine::task(task).fault); it runs no more.
    virtual void on_fault(std::size_t task) = 0;
    /// An activation was lost: Timer Task Error 0x6183 or Interrupt Task Error 0x6184.
    virtual void on_overrun(std::size_t task, std::uint16_t code) = 0;
};

/// The virtual CPU's speed.
struct CostModel {
    /// Virtual time one instruction takes; 0 makes every cycle instantaneous.
    std::uint64_t ns_per_instruction = 0;
    /// At most this many instructions run before the dispatcher looks again for a task of
    /// higher priority (one raised by an event while the CPU was busy).
    std::uint64_t quantum = 10'000;
};

/// Runs a program's tasks on one virtual CPU in virtual time, as IEC 61131-3 ed. 3, 6.8.2
/// describes a preemptive scheduler:
/// - the CPU runs the ready task of the highest PRIORITY (smaller number); among equals the one
///   already in its cycle, then the first in the task table;
/// - a cyclic task is released at start + n * INTERVAL (computed, so it never drifts); an event
///   task on the rising edge of its SINGLE BOOL (looked at after every cycle and on
///   check_event_inputs) or when the device raises its event;
/// - a task runs in slices that end at the first safe point after the next release of a task of
///   higher priority, which then runs on its own stack while the first stays suspended; the
///   instructions of a slice cost `ns_per_instruction` each, so the slice ends that much later;
/// - a release that finds its task still busy is lost and reported (0x6183, 0x6184);
/// - the watchdog is an instruction budget per cycle; a task that faults is stopped alone.
class TaskDispatcher {
public:
    TaskDispatcher(core::EventLoop& loop, Machine& machine, TaskHooks& hooks, CostModel cost);
    TaskDispatcher(const TaskDispatcher&) = delete;
    TaskDispatcher& operator=(const TaskDispatcher&) = delete;

    /// Releases every cyclic task now and runs what is ready; a start after a stop begins a new
    /// run (statistics, faults and event edges afresh; the watchdogs stay).
    void start();
    /// No more cycles; a cycle in progress is abandoned where it is.
    void stop();

    /// The device's event for an event task (a digital input edge, a CAN message or PDO, an
    /// error): releases it, or reports 0x6184 when it is still busy.
    void raise_event(std::size_t task);
    /// Looks for rising edges of the event tasks' SINGLE variables (after an online write) and
    /// runs what they release.
    void check_event_inputs();

    /// Puts the next release of every cyclic task whose interval is a whole multiple of
    /// `period` on the grid anchor + k * period (the first point at or after now): from then on
    /// the task runs in step with a clock of that period (the SYNC), a fixed time after its
    /// ticks. A task already on the grid, or within 1/8 period of it (real time sees ticks a
    /// little late), is left alone, so the device may call this at every tick.
    void align(core::TimePoint anchor, core::Duration period);

    /// Instructions one cycle of the task may execute (all its programs together).
    void set_watchdog(std::size_t task, std::uint64_t instructions);

    const TaskStatistics& statistics(std::size_t task) const { return slots_.at(task).statistics; }
    bool faulted(std::size_t task) const { return slots_.at(task).faulted; }

private:
    enum class Outcome : std::uint8_t { Suspended, Finished, Faulted };

    struct Slot {
        const Task* spec = nullptr;
        bool active = false;  ///< released and its cycle not finished
        bool started = false; ///< its cycle has begun (before_cycle ran)
        bool faulted = false;
        bool event_level = false;       ///< the SINGLE variable when last looked at
        core::TimePoint next_release{}; ///< cyclic tasks
        core::TimePoint due{};          ///< of the current activation
        core::TimePoint started_at{};
        std::size_t entry = 0;      ///< the program of the task that runs
        std::uint64_t executed = 0; ///< instructions of the current cycle
        std::uint64_t watchdog = kUnlimited;
        TaskStatistics statistics;
    };

    bool releases_cyclically(const Slot& slot) const;
    void dispatch();
    void release_on_rising_edges();
    void release_due_tasks();
    void release(std::size_t task, core::TimePoint due, std::uint16_t overrun_code);
    std::optional<std::size_t> next_to_run() const;
    std::uint64_t slice_for(std::size_t task) const;
    void begin_cycle(std::size_t task);
    void begin_entry(std::size_t task);
    Outcome run_slice(std::size_t task, std::uint64_t slice, std::uint64_t& executed);
    void end_slice(std::size_t task, Outcome outcome);
    void arm_wake_up();
    core::Duration cost_of(std::uint64_t instructions) const;

    core::EventLoop& loop_;
    Machine& machine_;
    TaskHooks& hooks_;
    CostModel cost_;
    std::vector<Slot> slots_;
    bool running_ = false;
    bool dispatching_ = false;
    bool slice_in_flight_ = false; ///< the CPU is busy until slice_end_ fires
    core::ScopedTimer wake_up_;
    core::ScopedTimer slice_end_;
};

} // namespace eposp::vm
