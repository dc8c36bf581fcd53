// The preemptive scheduler in virtual time: which task runs when, to the microsecond, under a
// cost model of 1 µs per instruction; overruns of cyclic and event tasks; the watchdog; the
// statistics. Programs are made with Builder so that their instruction counts are exact.

#include "eposp/vm/builder.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/runtime_error.hpp"
#include "eposp/vm/task_dispatcher.hpp"

#include <chrono>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <optional>

namespace eposp::vm {
namespace {

using namespace std::chrono_literals;

constexpr std::uint64_t kNsPerInstruction = 1000;

struct TaskSpec {
    std::string name;
    TaskKind kind = TaskKind::Cyclic;
    std::uint64_t interval_ns = 0;
    std::uint32_t priority = 0;
    /// Instructions of one cycle (at least 4), or none for an endless loop.
    std::optional<std::uint32_t> instructions;
};

// Records the hooks' calls as "<µs> <what> <task>", so a test reads as a timeline.
class Timeline : public TaskHooks {
public:
    explicit Timeline(core::EventLoop& loop) : loop_(loop) {}

    void before_cycle(std::size_t task) override { add("begin", task); }
    void after_cycle(std::size_t task) override { add("end", task); }
    void on_fault(std::size_t task) override { add("fault", task); }
    void on_overrun(std::size_t task, std::uint16_t code) override {
        add(fmt::format("overrun 0x{:04X}", code), task);
    }

    std::vector<std::string> events;
    std::vector<std::string> names;

private:
    void add(const std::string& what, std::size_t task) {
        events.push_back(fmt::format("{} {} {}", loop_.now().time_since_epoch().count() / 1000,
                                     what, names.at(task)));
    }
    core::EventLoop& loop_;
};

// A program that loops `instructions` long: i := 0; REPEAT i := i + 1 UNTIL i >= n (each
// iteration an add and a taken back-edge, a safe point), plus a Nop to make an odd count.
void emit_busy_program(Builder& b, std::uint32_t pou, std::uint32_t instance,
                       std::optional<std::uint32_t> instructions) {
    const auto iterations = static_cast<std::int32_t>(instructions ? (*instructions - 2) / 2 : 1);
    std::uint8_t limit[4];
    std::memcpy(limit, &iterations, 4);
    b.initialise(instance + 4, limit);
    b.begin_body(pou);
    auto loop = b.label();
    b.emit(Opcode::Ldi32, Operand::self(0), Operand::imm(0));
    if (instructions && *instructions % 2 == 1) {
        b.emit(Opcode::Nop);
    }
    b.bind(loop);
    b.emit(Opcode::AddI32, Operand::self(0), Operand::self(0),
           Operand::imm(instructions ? 1U : 0U));
    b.jump(Opcode::JLtI32, loop, Operand::self(0), Operand::self(4));
    b.emit(Opcode::Ret);
    b.end_body(0, 0);
}

class Dispatched {
public:
    explicit Dispatched(std::vector<TaskSpec> specs, std::uint64_t quantum = 10'000)
        : timeline(loop) {
        Builder b;
        for (const TaskSpec& spec : specs) {
            const auto pou = b.declare_pou(spec.name + "Program", PouKind::Program, 8);
            const auto instance = b.allocate(8, 4);
            emit_busy_program(b, pou, instance, spec.instructions);
            b.task(Task{.name = spec.name,
                        .kind = spec.kind,
                        .interval_ns = spec.interval_ns,
                        .event_offset = spec.kind == TaskKind::Event
                                            ? std::optional<std::uint32_t>(0)
                                            : std::nullopt,
                        .priority = spec.priority,
                        .stack_size = 64,
                        .entries = {TaskEntry{pou, instance}}});
            timeline.names.push_back(spec.name);
        }
        auto linked = link(*b.finish(), natives_);
        EXPECT_TRUE(linked) << linked.error();
        program_.emplace(std::move(*linked));
        machine.emplace(*program_);
        dispatcher.emplace(loop, *machine, timeline,
                           CostModel{.ns_per_instruction = kNsPerInstruction, .quantum = quantum});
    }

    core::EventLoop loop;
    Timeline timeline;
    std::optional<Machine> machine;
    std::optional<TaskDispatcher> dispatcher;

private:
    NativeRegistry natives_;
    std::optional<Program> program_;
};

TEST(TaskDispatcher, HigherPriorityPreemptsAtTheNextSafePointAndTheLowerResumes) {
    // High: 0.5 ms of work every 2 ms; Low: 5 ms of work every 10 ms.
    Dispatched d({{"High", TaskKind::Cyclic, 2'000'000, 0, 500},
                  {"Low", TaskKind::Cyclic, 10'000'000, 1, 5000}});
    d.dispatcher->start();
    d.loop.run_until(core::TimePoint{9ms});
    // Low's slices end at the first safe point (a back-edge, every 2 instructions) at or after
    // High's release: exactly at it when Low's instructions so far are odd (2 ms), one
    // instruction later otherwise (4 and 6 ms), which is High's jitter then.
    EXPECT_EQ(d.timeline.events,
              (std::vector<std::string>{"0 begin High", "500 end High", "500 begin Low",
                                        "2001 begin High", "2501 end High", // Low: 1501 done
                                        "4001 begin High", "4501 end High", // Low: 3001 done
                                        "6001 begin High", "6501 end High", // Low: 4501 done
                                        "7000 end Low", "8000 begin High", "8500 end High"}));
    const TaskStatistics& low = d.dispatcher->statistics(1);
    EXPECT_EQ(low.cycles, 1u);
    EXPECT_EQ(low.instructions_last, 5000u);
    EXPECT_EQ(low.execution_last, 5ms) << "time spent preempted is not execution time";
    EXPECT_EQ(low.jitter_last, 500us);
    const TaskStatistics& high = d.dispatcher->statistics(0);
    EXPECT_EQ(high.cycles, 5u);
    EXPECT_EQ(high.execution_min, 500us);
    EXPECT_EQ(high.execution_max, 500us);
    EXPECT_EQ(high.execution_average(), 500us);
    EXPECT_EQ(high.jitter_max, 1us);
}

TEST(TaskDispatcher, EqualPrioritiesRunInTableOrderWithoutPreemptingEachOther) {
    Dispatched d(
        {{"A", TaskKind::Cyclic, 3'000'000, 1, 2000}, {"B", TaskKind::Cyclic, 1'000'000, 1, 500}});
    d.dispatcher->start();
    d.loop.run_until(core::TimePoint{3ms});
    // Both are due at 0: A first, as the first in the table. B waits for A's whole cycle, so its
    // releases at 1 and 2 ms find its first activation still pending: two overruns.
    EXPECT_EQ(d.timeline.events,
              (std::vector<std::string>{"0 begin A", "1000 overrun 0x6183 B", "2000 end A",
                                        "2000 overrun 0x6183 B", "2000 begin B", "2500 end B",
                                        "3000 begin A"}));
    EXPECT_EQ(d.dispatcher->statistics(1).jitter_last, 2ms);
}

TEST(TaskDispatcher, CycleNIsDueAtStartPlusNIntervalsWithoutDrift) {
    Dispatched d({{"T", TaskKind::Cyclic, 1'000'000, 0, 333}});
    d.dispatcher->start();
    d.loop.run_until(core::TimePoint{1'000'000ms + 333us}); // the end of the cycle due then
    EXPECT_EQ(d.dispatcher->statistics(0).cycles, 1'000'001u);
    EXPECT_EQ(d.dispatcher->statistics(0).jitter_max, 0ns);
}

TEST(TaskDispatcher, AlignMovesTasksWhoseIntervalIsAMultipleOfTheClockOntoItsGrid) {
    // A 2 ms and a 1 ms task, and a 1.5 ms one that no 1 ms clock can carry.
    Dispatched d({{"Two", TaskKind::Cyclic, 2'000'000, 0, 100},
                  {"One", TaskKind::Cyclic, 1'000'000, 1, 100},
                  {"Odd", TaskKind::Cyclic, 1'500'000, 2, 100}});
    d.dispatcher->start();
    d.loop.run_until(core::TimePoint{1200us});
    d.timeline.events.clear();
    // A clock tick at 1.2 ms whose cycle should run 0.5 ms after it, at 1.7 ms.
    d.dispatcher->align(core::TimePoint{1700us}, 1ms);
    d.loop.run_until(core::TimePoint{3900us});
    EXPECT_EQ(d.timeline.events,
              (std::vector<std::string>{"1500 begin Odd", "1600 end Odd", "1700 begin Two",
                                        "1800 end Two", "1800 begin One", "1900 end One",
                                        "2700 begin One", "2800 end One", "3000 begin Odd",
                                        "3100 end Odd", "3700 begin Two", "3800 end Two",
                                        "3800 begin One", "3900 end One"}));
    // Aligning again at the next ticks changes nothing: the tasks are on the grid, or near
    // enough (a tick seen 100 us late, as real time may).
    d.dispatcher->align(core::TimePoint{4700us}, 1ms);
    d.dispatcher->align(core::TimePoint{3700us}, 1ms);
    d.dispatcher->align(core::TimePoint{4800us}, 1ms);
    d.timeline.events.clear();
    d.loop.run_until(core::TimePoint{4800us});
    EXPECT_EQ(d.timeline.events, (std::vector<std::string>{"4500 begin Odd", "4600 end Odd",
                                                           "4700 begin One", "4800 end One"}));
}

TEST(TaskDispatcher, CyclicTaskStillRunningAtItsNextReleaseIsATimerTaskError) {
    // 1.5 ms of work every 1 ms: the releases at 1 and 3 ms find it busy and are skipped.
    Dispatched d({{"Slow", TaskKind::Cyclic, 1'000'000, 0, 1500}});
    d.dispatcher->start();
    d.loop.run_until(core::TimePoint{4ms});
    EXPECT_EQ(d.timeline.events,
              (std::vector<std::string>{"0 begin Slow", "1000 overrun 0x6183 Slow", "1500 end Slow",
                                        "2000 begin Slow", "3000 overrun 0x6183 Slow",
                                        "3500 end Slow", "4000 begin Slow"}));
    EXPECT_EQ(d.dispatcher->statistics(0).overruns, 2u);
    EXPECT_EQ(d.dispatcher->statistics(0).cycles, 2u);
}

TEST(TaskDispatcher, EventTaskRunsOnTheDeviceEventAndPreemptsLowerPriority) {
    Dispatched d({{"Background", TaskKind::Cyclic, 10'000'000, 5, 4000},
                  {"OnInput", TaskKind::Event, 0, 1, 200}},
                 /*quantum=*/100);
    d.dispatcher->start();
    d.loop.at(core::TimePoint{1ms}, [&d] { d.dispatcher->raise_event(1); });
    d.loop.run_until(core::TimePoint{5ms});
    // The event arrives during a slice of Background: slices of at least 100 instructions end
    // at back-edges, at 101 µs, then every 102 µs; the one running at 1 ms ends at 1019 µs.
    EXPECT_EQ(d.timeline.events,
              (std::vector<std::string>{"0 begin Background", "1019 begin OnInput",
                                        "1219 end OnInput", "4200 end Background"}));
    EXPECT_EQ(d.dispatcher->statistics(1).jitter_last, 19us);
}

TEST(TaskDispatcher, EventTaskTriggeredWhileRunningIsAnInterruptTaskError) {
    Dispatched d({{"OnInput", TaskKind::Event, 0, 0, 1000}});
    d.dispatcher->start();
    d.loop.at(core::TimePoint{0ms}, [&d] { d.dispatcher->raise_event(0); });
    d.loop.at(core::TimePoint{500us}, [&d] { d.dispatcher->raise_event(0); });
    d.loop.at(core::TimePoint{2ms}, [&d] { d.dispatcher->raise_event(0); });
    d.loop.run_until(core::TimePoint{5ms});
    EXPECT_EQ(
        d.timeline.events,
        (std::vector<std::string>{"0 begin OnInput", "500 overrun 0x6184 OnInput",
                                  "1000 end OnInput", "2000 begin OnInput", "3000 end OnInput"}));
    EXPECT_EQ(d.dispatcher->statistics(0).overruns, 1u);
}

TEST(TaskDispatcher, WatchdogStopsAnEndlessLoopAndTheOtherTasksGoOn) {
    Dispatched d({{"Fast", TaskKind::Cyclic, 1'000'000, 0, 100},
                  {"Stuck", TaskKind::Cyclic, 10'000'000, 1, std::nullopt}});
    d.dispatcher->set_watchdog(1, 2'500);
    d.dispatcher->start();
    d.loop.run_until(core::TimePoint{5ms});
    EXPECT_TRUE(d.dispatcher->faulted(1));
    EXPECT_EQ(d.machine->task(1).fault.trap, Trap::BudgetExceeded);
    // Stuck runs from 0.1 ms, preempted by Fast at the safe points after 1 and 2 ms (901 and
    // 1801 instructions done); its budget of 2500 runs out 700 instructions after 2.101 ms.
    EXPECT_EQ(d.timeline.events,
              (std::vector<std::string>{"0 begin Fast", "100 end Fast", "100 begin Stuck",
                                        "1001 begin Fast", "1101 end Fast", "2001 begin Fast",
                                        "2101 end Fast", "2801 fault Stuck", "3000 begin Fast",
                                        "3100 end Fast", "4000 begin Fast", "4100 end Fast",
                                        "5000 begin Fast"}));
}

TEST(TaskDispatcher, StopAbandonsTheCycleAndReleasesNothingMore) {
    Dispatched d({{"T", TaskKind::Cyclic, 1'000'000, 0, 600}});
    d.dispatcher->start();
    d.loop.run_until(core::TimePoint{1100us});
    d.dispatcher->stop();
    d.loop.run_until(core::TimePoint{10ms});
    EXPECT_EQ(d.timeline.events,
              (std::vector<std::string>{"0 begin T", "600 end T", "1000 begin T"}));
}

} // namespace
} // namespace eposp::vm
