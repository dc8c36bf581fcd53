// The interpreter's dispatch against native code on the same work: the bubble sort of
// ../shared/bench/bubble_sort.st (256 DINTs from a congruential generator, sorted, checksum),
// hand-assembled the way straightforward code generation would emit it, and the same in C++.
// The ratio of the two times is the figure to watch.

#include "eposp/vm/builder.hpp"
#include "eposp/vm/machine.hpp"

#include <array>
#include <benchmark/benchmark.h>
#include <cstring>
#include <stdexcept>

namespace {

using namespace eposp::vm;

std::int32_t native_sort(std::int32_t seed) {
    std::array<std::int32_t, 256> a;
    std::int32_t x = seed;
    for (int i = 0; i <= 255; ++i) {
        x = (x * 75 + 74) % 65537;
        if (x < 0) {
            x = -x;
        }
        a[i] = x % 10000;
    }
    for (int i = 0; i <= 254; ++i) {
        for (int j = 0; j <= 254 - i; ++j) {
            if (a[j] > a[j + 1]) {
                std::swap(a[j], a[j + 1]);
            }
        }
    }
    return a[0] + a[128] * 3 + a[255] * 7;
}

// Main's instance: seed, checksum, x, i, j, j1, limit, t1, t2, then a : ARRAY[0..255] OF DINT.
constexpr std::uint32_t kSeed = 0, kChecksum = 4, kX = 8, kI = 12, kJ = 16, kJ1 = 20, kLimit = 24,
                        kT1 = 28, kT2 = 32, kArray = 36;

Image assemble_sort() {
    Builder b;
    const auto main = b.declare_pou("Main", PouKind::Program, kArray + 256 * 4);
    const auto instance = b.allocate(kArray + 256 * 4, 8);
    const auto zero = Operand::global(b.constant(std::int32_t{0}));
    const auto c75 = Operand::global(b.constant(std::int32_t{75}));
    const auto c65537 = Operand::global(b.constant(std::int32_t{65537}));
    const auto c10000 = Operand::global(b.constant(std::int32_t{10000}));
    const auto c254 = Operand::global(b.constant(std::int32_t{254}));
    const auto c255 = Operand::global(b.constant(std::int32_t{255}));
    const auto c3 = Operand::global(b.constant(std::int32_t{3}));
    const auto c7 = Operand::global(b.constant(std::int32_t{7}));
    const auto a = b.array({0, 256, 4});
    const auto v = [](std::uint32_t offset) {
        return Operand::self(offset);
    };
    const auto one = Operand::imm(1);

    b.begin_body(main);
    auto fill = b.label(), positive = b.label(), outer = b.label(), inner = b.label(),
         no_swap = b.label(), inner_done = b.label();
    // FOR loops as code generation emits them: test once before the first iteration, then
    // the For back-edge (increment, compare, branch) at the end of the body.
    b.emit(Opcode::Mov32, v(kX), v(kSeed));
    b.emit(Opcode::Ldi32, v(kI), Operand::imm(0));
    b.bind(fill);
    b.emit(Opcode::Mul32, v(kT1), v(kX), c75);
    b.emit(Opcode::AddI32, v(kT1), v(kT1), Operand::imm(74));
    b.emit(Opcode::ModI32, v(kX), v(kT1), c65537);
    b.jump(Opcode::JLeI32, positive, zero, v(kX));
    b.emit(Opcode::Neg32, v(kX), v(kX));
    b.bind(positive);
    b.emit(Opcode::ModI32, v(kT1), v(kX), c10000);
    b.emit(Opcode::Stx32, v(kArray), v(kI), v(kT1), a);
    b.for_loop(Opcode::ForI32, fill, v(kI), c255, 1);

    b.emit(Opcode::Ldi32, v(kI), Operand::imm(0));
    b.bind(outer);
    b.emit(Opcode::Ldi32, v(kJ), Operand::imm(0));
    b.emit(Opcode::Sub32, v(kLimit), c254, v(kI));
    b.jump(Opcode::JLtI32, inner_done, v(kLimit), v(kJ));
    b.bind(inner);
    b.emit(Opcode::AddI32, v(kJ1), v(kJ), one);
    b.emit(Opcode::Ldx32, v(kT1), v(kArray), v(kJ), a);
    b.emit(Opcode::Ldx32, v(kT2), v(kArray), v(kJ1), a);
    b.jump(Opcode::JLeI32, no_swap, v(kT1), v(kT2));
    b.emit(Opcode::Stx32, v(kArray), v(kJ), v(kT2), a);
    b.emit(Opcode::Stx32, v(kArray), v(kJ1), v(kT1), a);
    b.bind(no_swap);
    b.for_loop(Opcode::ForI32, inner, v(kJ), v(kLimit), 1);
    b.bind(inner_done);
    b.for_loop(Opcode::ForI32, outer, v(kI), c254, 1);

    b.emit(Opcode::Mul32, v(kT1), v(kArray + 128 * 4), c3);
    b.emit(Opcode::Mul32, v(kT2), v(kArray + 255 * 4), c7);
    b.emit(Opcode::Add32, v(kChecksum), v(kArray), v(kT1));
    b.emit(Opcode::Add32, v(kChecksum), v(kChecksum), v(kT2));
    b.emit(Opcode::Ret);
    b.end_body(0);
    b.task(Task{.name = "MainTask",
                .kind = TaskKind::Cyclic,
                .interval_ns = 1'000'000,
                .stack_size = 256,
                .entries = {{main, instance}}});
    return std::move(*b.finish());
}

void BM_BubbleSort256_Native(benchmark::State& state) {
    std::int32_t seed = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(native_sort(++seed));
    }
}
BENCHMARK(BM_BubbleSort256_Native);

void BM_BubbleSort256_Vm(benchmark::State& state) {
    NativeRegistry natives;
    auto program = link(assemble_sort(), natives);
    if (!program) {
        state.SkipWithError(program.error().c_str());
        return;
    }
    Machine machine(*program);
    const auto instance = program->image().tasks[0].entries[0].instance;
    std::int32_t seed = 0;
    for (auto _ : state) {
        ++seed;
        std::memcpy(machine.memory().data() + instance + kSeed, &seed, 4);
        machine.run_cycle(0);
        std::int32_t checksum;
        std::memcpy(&checksum, machine.memory().data() + instance + kChecksum, 4);
        if (seed == 1 && checksum != native_sort(seed)) {
            state.SkipWithError("VM and native results differ");
            return;
        }
        benchmark::DoNotOptimize(checksum);
    }
    state.counters["instructions"] = static_cast<double>(machine.task(0).executed);
}
BENCHMARK(BM_BubbleSort256_Vm);

} // namespace
