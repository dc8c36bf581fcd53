#include "eposp/can/virtual_bus.hpp"

#include <benchmark/benchmark.h>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace {

using eposp::can::BusConfig;
using eposp::can::Frame;
using eposp::can::VirtualBus;
using eposp::can::VirtualPort;
using eposp::core::EventLoop;

constexpr std::size_t kFramesPerPort = 1000;

// Frames per wall-clock second through a fully loaded 1 Mbit/s bus: every port queues
// kFramesPerPort frames at once, so each frame goes through arbitration against all ports,
// delivery to all others and the observer. "bus_time" is simulated bus seconds per wall
// second: how much faster than real time a saturated bus runs.
void BM_SaturatedBus(benchmark::State& state) {
    const auto port_count = static_cast<std::size_t>(state.range(0));
    std::uint64_t frames = 0;
    double simulated_seconds = 0;
    for (auto _ : state) {
        EventLoop loop;
        VirtualBus bus(loop, BusConfig{.tx_queue_capacity = kFramesPerPort});
        std::uint64_t observed = 0;
        bus.add_observer([&observed](const eposp::can::WireEvent&) { ++observed; });
        std::vector<std::unique_ptr<VirtualPort>> ports;
        std::uint64_t received = 0;
        for (std::size_t i = 0; i < port_count; ++i) {
            ports.push_back(bus.connect("node" + std::to_string(i)));
            ports.back()->on_receive([&received](const Frame&) { ++received; });
        }
        for (std::size_t n = 0; n < kFramesPerPort; ++n) {
            for (std::size_t i = 0; i < port_count; ++i) {
                const auto id = static_cast<std::uint32_t>(0x180 + i);
                ports[i]->send(
                    Frame::data_frame(id, {1, 2, 3, 4, 5, 6, 7, static_cast<std::uint8_t>(n)}));
            }
        }
        loop.run();
        benchmark::DoNotOptimize(received);
        frames += observed;
        simulated_seconds += std::chrono::duration<double>(loop.now().time_since_epoch()).count();
    }
    state.counters["frames"] =
        benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
    state.counters["bus_time"] = benchmark::Counter(simulated_seconds, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SaturatedBus)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

} // namespace
