// What the PLC runtime costs around the programs it runs: a task switch (suspending a task at a
// safe point and resuming another on its own stack), a whole task cycle on the event loop, and
// the copy of the process image in and out of located variables.

#include "eposp/core/event_loop.hpp"
#include "eposp/vm/builder.hpp"
#include "eposp/vm/plc_runtime.hpp"
#include "eposp/vm/process_image.hpp"

#include <benchmark/benchmark.h>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <vector>

namespace {

using namespace eposp;
using namespace eposp::vm;

// One cyclic task of 1 ms per element, task t of priority t, running a program that counts
// `iterations[t]` times (one add and one back-edge, a safe point, per iteration), or without end
// for nullopt.
Image counting_tasks(const std::vector<std::optional<std::int32_t>>& iterations_per_task) {
    Builder b;
    for (std::uint32_t t = 0; t < iterations_per_task.size(); ++t) {
        const std::optional<std::int32_t> iterations = iterations_per_task[t];
        const auto pou = b.declare_pou("P" + std::to_string(t), PouKind::Program, 8);
        const auto instance = b.allocate(8, 4);
        const std::int32_t limit = iterations.value_or(1);
        std::uint8_t bytes[4];
        std::memcpy(bytes, &limit, 4);
        b.initialise(instance + 4, bytes);
        b.begin_body(pou);
        auto loop = b.label();
        b.emit(Opcode::Ldi32, Operand::self(0), Operand::imm(0));
        b.bind(loop);
        b.emit(Opcode::AddI32, Operand::self(0), Operand::self(0),
               Operand::imm(iterations ? 1U : 0U));
        b.jump(Opcode::JLtI32, loop, Operand::self(0), Operand::self(4));
        b.emit(Opcode::Ret);
        b.end_body(0, 0);
        b.task(Task{.name = "T" + std::to_string(t),
                    .kind = TaskKind::Cyclic,
                    .interval_ns = 1'000'000,
                    .priority = t,
                    .stack_size = 64,
                    .entries = {TaskEntry{pou, instance}}});
    }
    auto image = b.finish();
    if (!image) {
        throw std::runtime_error(image.error());
    }
    return std::move(*image);
}

// Two tasks suspended and resumed alternately after every safe point: each run() is one switch
// (restore an activation, two instructions, save it). Against BM_UninterruptedLoop, the same
// instructions without switching, it gives the cost of a switch.
void BM_TaskSwitch(benchmark::State& state) {
    NativeRegistry natives;
    const auto program = link(counting_tasks({std::nullopt, std::nullopt}), natives);
    Machine machine(*program);
    machine.start(0, 0);
    machine.start(1, 0);
    for (auto _ : state) {
        machine.run(0, 0);
        machine.run(1, 0);
    }
    state.counters["per_switch"] =
        benchmark::Counter(static_cast<double>(state.iterations() * 2),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TaskSwitch);

void BM_UninterruptedLoop(benchmark::State& state) {
    constexpr std::int32_t kIterations = 100'000;
    NativeRegistry natives;
    const auto program = link(counting_tasks({kIterations}), natives);
    Machine machine(*program);
    for (auto _ : state) {
        machine.run_cycle(0);
    }
    state.counters["per_iteration"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * kIterations,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_UninterruptedLoop);

// One whole cycle of a 4-instruction program as the runtime runs it on the event loop: the
// release timer, the dispatch, the hooks around the cycle (inputs, markers and forced values
// in; outputs out, with no located variables here) and the statistics.
void BM_RuntimeCycle(benchmark::State& state) {
    core::EventLoop loop;
    NativeRegistry natives;
    PlcRuntime runtime(loop, natives, {}, {});
    if (runtime.load(counting_tasks({1})) || runtime.start(StartMode::Cold)) {
        throw std::runtime_error("cannot start");
    }
    for (auto _ : state) {
        loop.run_for(std::chrono::milliseconds(1));
    }
    state.counters["per_cycle"] =
        benchmark::Counter(static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_RuntimeCycle);

// Preemption on the event loop: T0 (priority 0, 4 instructions) every 10 µs interrupts T1
// (priority 1), which counts without end, under a cost model of 100 ns per instruction. One
// iteration is one 10 µs period: T1's slice ends at T0's release, T0 runs its cycle, T1 resumes;
// about 96 of T1's instructions run in between (BM_UninterruptedLoop gives their cost).
void BM_RuntimePreemption(benchmark::State& state) {
    core::EventLoop loop;
    NativeRegistry natives;
    RuntimeConfig config;
    config.cost.ns_per_instruction = 100;
    PlcRuntime runtime(loop, natives, config, {});
    Image image = counting_tasks({1, std::nullopt});
    image.tasks[0].interval_ns = 10'000;
    image.tasks[1].interval_ns = 1'000'000'000'000; // never due again while measured
    if (runtime.load(std::move(image))) {
        throw std::runtime_error("cannot load");
    }
    runtime.set_watchdog(1, kUnlimited);
    if (runtime.start(StartMode::Cold)) {
        throw std::runtime_error("cannot start");
    }
    for (auto _ : state) {
        loop.run_for(std::chrono::microseconds(10));
    }
    state.counters["per_period"] =
        benchmark::Counter(static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_RuntimePreemption);

// Copying a task's located variables in and out: all 96 input and 96 output entries bound (the
// whole DS-405 image of the EPOS P), as read_inputs before and write_outputs after a cycle.
void BM_ProcessImageCopy(benchmark::State& state) {
    std::vector<IoBinding> bindings;
    std::uint32_t offset = kNullGuardSize;
    for (const IoArea area : {IoArea::Input, IoArea::Output}) {
        const auto& objects = area == IoArea::Input ? kInputObjects : kOutputObjects;
        for (const ProcessImageObject& object : objects) {
            const std::uint32_t size = scalar_size(object.type);
            for (std::uint32_t entry = 0; entry < kEntriesPerObject; ++entry) {
                bindings.push_back(
                    {area, object.type, object.first_byte + entry * size, 0, offset});
                offset += 4;
            }
        }
    }
    std::vector<std::uint8_t> memory(offset);
    ProcessImage image;
    for (auto _ : state) {
        image.read_inputs(bindings, memory);
        image.write_outputs(bindings, memory);
        benchmark::DoNotOptimize(memory.data());
        benchmark::DoNotOptimize(image.outputs().data());
    }
    state.counters["per_entry"] =
        benchmark::Counter(static_cast<double>(state.iterations() * bindings.size()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ProcessImageCopy);

} // namespace

BENCHMARK_MAIN();
