// Cyclic tasks on the event loop, in virtual time: each at its INTERVAL without drift, the
// higher priority first when two are due at once, a faulting task stopped alone.

#include "eposp/vm/builder.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/task_scheduler.hpp"

#include <chrono>
#include <cstring>
#include <gtest/gtest.h>
#include <optional>

namespace eposp::vm {
namespace {

using namespace std::chrono_literals;

// Static data: a DINT counting every cycle of any task, then per task the count at its last
// cycle (its place in the order of execution).
constexpr std::uint32_t kSequence = kNullGuardSize;
constexpr std::uint32_t kLastSeen = kSequence + 4;

struct TaskSpec {
    std::uint64_t interval_ns;
    std::uint32_t priority;
    bool divides_by_zero = false;
};

class Scheduled {
public:
    explicit Scheduled(std::initializer_list<TaskSpec> specs) {
        Builder builder;
        builder.allocate(4 + 4 * static_cast<std::uint32_t>(specs.size()), 4);
        std::uint32_t index = 0;
        for (const TaskSpec& spec : specs) {
            const auto pou = builder.declare_pou("P" + std::to_string(index), PouKind::Program, 4);
            const auto instance = builder.allocate(4, 4);
            builder.begin_body(pou);
            builder.emit(Opcode::AddI32, Operand::global(kSequence), Operand::global(kSequence),
                         Operand::imm(1));
            builder.emit(Opcode::Mov32, Operand::global(kLastSeen + 4 * index),
                         Operand::global(kSequence));
            if (spec.divides_by_zero) {
                builder.emit(Opcode::DivI32, Operand::self(0), Operand::self(0), Operand::self(0));
            }
            builder.emit(Opcode::Ret);
            builder.end_body(0, 0);
            builder.task(Task{"T" + std::to_string(index),
                              TaskKind::Cyclic,
                              spec.interval_ns,
                              0,
                              spec.priority,
                              256,
                              {TaskEntry{pou, instance}}});
            ++index;
        }
        auto linked = link(*builder.finish(), natives_);
        EXPECT_TRUE(linked) << linked.error();
        program_.emplace(std::move(*linked));
        machine_.emplace(*program_);
        scheduler_.emplace(loop, *machine_);
    }

    TaskScheduler& scheduler() { return *scheduler_; }
    std::int32_t last_seen(std::uint32_t task) const {
        std::int32_t value;
        std::memcpy(&value, machine_->memory().data() + kLastSeen + 4 * task, 4);
        return value;
    }

    core::EventLoop loop;

private:
    NativeRegistry natives_;
    std::optional<Program> program_;
    std::optional<Machine> machine_;
    std::optional<TaskScheduler> scheduler_;
};

TEST(TaskScheduler, EachTaskRunsAtItsIntervalFromTheStart) {
    Scheduled s{{2'000'000, 1}, {3'000'000, 0}};
    s.scheduler().start();
    s.loop.run_until(core::TimePoint{10ms});
    EXPECT_EQ(s.scheduler().cycles(0), 6u); // 0, 2, 4, 6, 8, 10 ms
    EXPECT_EQ(s.scheduler().cycles(1), 4u); // 0, 3, 6, 9 ms
}

TEST(TaskScheduler, HigherPriorityRunsFirstWhenBothAreDue) {
    // At 6 ms both are due; the 3 ms task was last re-armed before the 2 ms one, so only the
    // priorities can put the 2 ms task (priority 0) first.
    Scheduled s{{2'000'000, 0}, {3'000'000, 1}};
    s.scheduler().start();
    s.loop.run_until(core::TimePoint{6ms});
    EXPECT_LT(s.last_seen(0), s.last_seen(1));
}

TEST(TaskScheduler, EqualPrioritiesRunInTableOrder) {
    Scheduled s{{1'000'000, 3}, {1'000'000, 3}};
    s.scheduler().start();
    s.loop.run_until(core::TimePoint{5ms});
    EXPECT_EQ(s.last_seen(0) + 1, s.last_seen(1));
}

TEST(TaskScheduler, NoDriftOverAMillionCycles) {
    Scheduled s{{1'000'000, 0}};
    s.scheduler().start();
    s.loop.run_until(core::TimePoint{1'000'000ms});
    EXPECT_EQ(s.scheduler().cycles(0), 1'000'001u);
}

TEST(TaskScheduler, FaultingTaskStopsAndTheOthersGoOn) {
    Scheduled s{{1'000'000, 0, true}, {1'000'000, 1}};
    std::vector<std::size_t> faulted;
    s.scheduler().on_fault([&faulted](std::size_t task) { faulted.push_back(task); });
    s.scheduler().start();
    s.loop.run_until(core::TimePoint{4ms});
    EXPECT_EQ(faulted, std::vector<std::size_t>{0});
    EXPECT_TRUE(s.scheduler().faulted(0));
    EXPECT_EQ(s.scheduler().cycles(0), 0u);
    EXPECT_EQ(s.scheduler().cycles(1), 5u);
}

TEST(TaskScheduler, StopEndsTheCycles) {
    Scheduled s{{1'000'000, 0}};
    s.scheduler().start();
    s.loop.run_until(core::TimePoint{2ms});
    s.scheduler().stop();
    s.loop.run_until(core::TimePoint{10ms});
    EXPECT_EQ(s.scheduler().cycles(0), 3u);
}

} // namespace
} // namespace eposp::vm
