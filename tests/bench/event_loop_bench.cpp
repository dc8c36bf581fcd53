#include "eposp/core/event_loop.hpp"

#include <benchmark/benchmark.h>

namespace {

using eposp::core::Duration;
using eposp::core::EventLoop;

// The cost of one timer event: the figure that bounds how many 10 kHz drive models and 1 ms
// PLC tasks one core can simulate faster than real time.
void BM_PeriodicTimers(benchmark::State& state) {
    const auto timers = static_cast<int>(state.range(0));
    for (auto _ : state) {
        EventLoop loop;
        std::uint64_t fired = 0;
        for (int i = 0; i < timers; ++i) {
            loop.every(std::chrono::microseconds(100 + i), [&fired] { ++fired; });
        }
        loop.run_for(std::chrono::milliseconds(100));
        benchmark::DoNotOptimize(fired);
        state.counters["events"] = benchmark::Counter(
            static_cast<double>(fired), benchmark::Counter::kIsIterationInvariantRate);
    }
}
BENCHMARK(BM_PeriodicTimers)->Arg(1)->Arg(8)->Arg(64);

} // namespace
