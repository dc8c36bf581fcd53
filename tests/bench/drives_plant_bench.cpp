#include "../drives/plant_test_motor.hpp"
#include "eposp/drives/motion/profile_position_generator.hpp"
#include "eposp/drives/plant/servo_axis.hpp"

#include <benchmark/benchmark.h>
#include <vector>

namespace {

using namespace eposp::drives;

// N axes in position control, each following its own back-and-forth Profile Position move: the
// generator at 1 kHz, the position loop at 1 kHz, current loop and plant at 10 kHz. One
// iteration is one simulated millisecond of every axis; "simulated_s" is simulated seconds per
// wall-clock second (issue 6 asks ≥ 100 for 8 whole drives).
void BM_ServoAxes(benchmark::State& state) {
    const auto count = static_cast<std::size_t>(state.range(0));
    std::vector<plant::ServoAxis> axes(count, plant::ServoAxis(plant::test::tuned_axis()));
    std::vector<motion::ProfilePositionGenerator> generators(count);
    const motion::ProfileParameters profile{50000, 200000, 200000, motion::RampShape::SinSquared};
    for (auto& axis : axes) {
        axis.set_mode(plant::ControlMode::Position);
    }
    double now = 0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < count; ++i) {
            if (generators[i].finished(now)) {
                const double target = generators[i].demand_target() > 0 ? 0.0 : 20000.0;
                generators[i].new_setpoint(now, {target, false, profile}, true);
            }
            const motion::MotionState demand = generators[i].update(now);
            axes[i].set_demand({demand.position, demand.velocity, demand.acceleration, 0});
            for (int step = 0; step < plant::ServoAxis::kCurrentStepsPerOuterLoop; ++step) {
                axes[i].step();
            }
            benchmark::DoNotOptimize(axes[i].position_actual());
        }
        now += plant::ServoAxis::kOuterLoopPeriod;
    }
    state.counters["simulated_s"] = benchmark::Counter(
        plant::ServoAxis::kOuterLoopPeriod, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_ServoAxes)->Arg(1)->Arg(8)->Arg(32);

} // namespace
