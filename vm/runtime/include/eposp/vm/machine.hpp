#pragma once

#include "eposp/vm/coverage_report.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/task_state.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace eposp::vm {

namespace detail {
struct CoverageCounters;
}

/// Whether a machine counts the lines and branches it runs (docs/runtime.md, "Coverage").
/// Recording runs the interpreter, also for a program that has compiled code.
enum class Coverage : std::uint8_t { Off, Record };

/// A program's memory (static data followed by one stack per task) and the state of its
/// tasks. Running allocates nothing: everything is sized here, from the verified image.
class Machine {
public:
    explicit Machine(const Program& program, Coverage coverage = Coverage::Off);
    ~Machine();
    Machine(Machine&&) noexcept;

    /// Static data back to its initial values; every task idle.
    void cold_start();

    /// Begins a run of program `entry` of `task` (the watchdog count starts again).
    void start(std::size_t task, std::size_t entry);
    /// Continues the task: until it returns (Finished), a run-time error (Faulted), or the
    /// first safe point after `slice` more instructions (Suspended, resumable with run).
    RunState run(std::size_t task, std::uint64_t slice = kUnlimited);
    /// Runs every program of the task once, in order; stops at the first fault.
    RunState run_cycle(std::size_t task);

    void set_budget(std::size_t task, std::uint64_t instructions);
    const TaskState& task(std::size_t task) const { return tasks_.at(task); }
    /// "division by zero in Main at line 12" for a faulted task.
    std::string describe_fault(std::size_t task) const;

    /// The lines and branches run since construction (cold starts included), by POU; empty
    /// with Coverage::Off.
    CoverageReport coverage() const;

    const Program& program() const { return program_; }
    std::span<std::uint8_t> memory() { return memory_; }
    std::span<const std::uint8_t> memory() const { return memory_; }

private:
    const Program& program_;
    std::vector<std::uint8_t> memory_;
    std::vector<TaskState> tasks_;
    std::unique_ptr<detail::CoverageCounters> coverage_;
};

} // namespace eposp::vm
