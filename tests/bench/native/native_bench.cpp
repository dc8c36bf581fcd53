// µs per scan of each hand-translated benchmark program. Benchmarks are registered from the
// program registry under "native/<program>", so that a VM benchmark registering
// "vm/<program>" in the same binary is measured with the same batch and the same clock.

#include "eposp/bench/native/expected_results.hpp"
#include "eposp/bench/native/program.hpp"

#include <benchmark/benchmark.h>
#include <string>

namespace {

using eposp::bench::native::kCheckedScans;
using eposp::bench::native::ProgramEntry;

// One iteration runs a fresh instance for the same 1000 scans as the correctness table, so the
// work per iteration does not depend on how many iterations the library chooses.
void BM_NativeScans(benchmark::State& state, const ProgramEntry& entry) {
    for (auto _ : state) {
        state.PauseTiming();
        auto program = entry.make();
        state.ResumeTiming();
        eposp::bench::native::run_scans(*program, kCheckedScans);
        benchmark::DoNotOptimize(program->globals());
    }
    // CPU seconds per scan, printed with an SI prefix ("66.2us").
    state.counters["per_scan"] = benchmark::Counter(static_cast<double>(kCheckedScans),
                                                    benchmark::Counter::kIsIterationInvariantRate |
                                                        benchmark::Counter::kInvert);
}

} // namespace

int main(int argc, char** argv) {
    for (const ProgramEntry& entry : eposp::bench::native::programs()) {
        benchmark::RegisterBenchmark(("native/" + std::string(entry.name)).c_str(), BM_NativeScans,
                                     entry)
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
