#include "eposp/test/moving_epos2_network.hpp"

#include <benchmark/benchmark.h>

namespace {

// N whole simulated EPOS2s on one virtual bus, always moving (test::MovingEpos2Network). One
// iteration is one simulated millisecond; "simulated_s" is simulated seconds per second (issue 19
// asks ≥ 200 for 8 drives).
void BM_Epos2Network(benchmark::State& state) {
    eposp::core::EventLoop loop;
    eposp::test::MovingEpos2Network network(loop, static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        network.run_millisecond();
    }
    state.counters["simulated_s"] =
        benchmark::Counter(1e-3, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Epos2Network)->Arg(1)->Arg(8)->Arg(32);
// Always the same 2000 simulated ms of 8 drives: what callgrind counts per simulated ms is then
// the same to the instruction on every run (docs/performance.md).
BENCHMARK(BM_Epos2Network)->Name("BM_Epos2Network2000ms")->Arg(8)->Iterations(2000);

} // namespace
