// The VM against native code on the seven benchmark programs of ../shared/bench: each program
// compiled from its ST source and run by the VM, and its hand translation compiled -O2, timed
// in the same run by the same library; at the end a table of VM time / native time per program
// and their geometric mean (the figure of docs/performance.md).

#include "eposp/bench/native/expected_results.hpp"
#include "eposp/bench/native/program.hpp"
#include "eposp/compiler/compiler.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"

#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace {

using eposp::bench::native::kCheckedScans;
using eposp::bench::native::kScanInterval;
using eposp::bench::native::ProgramEntry;

/// One benchmark program compiled from its ST source, ready to scan from its cold start.
class VmProgram {
public:
    explicit VmProgram(std::string_view name) {
        eposp::vm::stdlib::register_standard_library(natives_);
        eposp::vm::stdlib::register_clock(natives_, [this] { return now_ns_; });
        eposp::compiler::SourceManager sources;
        eposp::compiler::Diagnostics diagnostics;
        const auto file =
            sources.load(std::string(EPOSP_BENCH_PROGRAMS) + "/" + std::string(name) + ".st");
        if (!file) {
            throw std::runtime_error(file.error());
        }
        auto image = eposp::compiler::compile(sources, std::span(&*file, 1), diagnostics);
        if (!image) {
            throw std::runtime_error(eposp::compiler::render(diagnostics, sources));
        }
        auto linked = eposp::vm::link(std::move(*image), natives_);
        if (!linked) {
            throw std::runtime_error(linked.error());
        }
        program_.emplace(std::move(*linked));
        machine_.emplace(*program_);
    }

    void run_scans(std::int32_t scans) {
        machine_->cold_start();
        for (std::int32_t scan = 0; scan < scans; ++scan) {
            now_ns_ = scan * kScanInterval.count();
            if (machine_->run_cycle(0) != eposp::vm::RunState::Finished) {
                throw std::runtime_error(machine_->describe_fault(0));
            }
        }
    }

private:
    std::int64_t now_ns_ = 0;
    eposp::vm::NativeRegistry natives_;
    std::optional<eposp::vm::Program> program_;
    std::optional<eposp::vm::Machine> machine_;
};

void report_per_scan(benchmark::State& state) {
    state.counters["per_scan"] = benchmark::Counter(static_cast<double>(kCheckedScans),
                                                    benchmark::Counter::kIsIterationInvariantRate |
                                                        benchmark::Counter::kInvert);
}

// Both sides run the same 1000 scans from a cold start per iteration.
void BM_Vm(benchmark::State& state, std::shared_ptr<VmProgram> program) {
    for (auto _ : state) {
        program->run_scans(kCheckedScans);
    }
    report_per_scan(state);
}

void BM_Native(benchmark::State& state, const ProgramEntry& entry) {
    for (auto _ : state) {
        state.PauseTiming();
        auto program = entry.make();
        state.ResumeTiming();
        eposp::bench::native::run_scans(*program, kCheckedScans);
        benchmark::DoNotOptimize(program->globals());
    }
    report_per_scan(state);
}

/// Keeps the CPU time per iteration of every run (the median of repetitions where asked).
class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            const bool aggregate = run.run_type == Run::RT_Aggregate;
            if (!aggregate || run.aggregate_name == "median") {
                cpu_time_[run.run_name.function_name] = run.GetAdjustedCPUTime();
            }
        }
    }

    void print_ratios() const {
        std::printf("\n%-14s %12s %12s %8s\n", "program", "vm", "native", "ratio");
        double log_sum = 0;
        int count = 0;
        for (const ProgramEntry& entry : eposp::bench::native::programs()) {
            const auto vm = cpu_time_.find("vm/" + std::string(entry.name));
            const auto native = cpu_time_.find("native/" + std::string(entry.name));
            if (vm == cpu_time_.end() || native == cpu_time_.end()) {
                continue;
            }
            const double ratio = vm->second / native->second;
            std::printf("%-14s %9.1f us %9.1f us %7.2fx\n", std::string(entry.name).c_str(),
                        vm->second / kCheckedScans * 1000, native->second / kCheckedScans * 1000,
                        ratio);
            log_sum += std::log(ratio);
            ++count;
        }
        if (count > 0) {
            std::printf("%-14s %36.2fx\n", "geometric mean", std::exp(log_sum / count));
        }
    }

private:
    std::map<std::string, double> cpu_time_; // ms per iteration (1000 scans)
};

} // namespace

int main(int argc, char** argv) {
    for (const ProgramEntry& entry : eposp::bench::native::programs()) {
        const std::string name(entry.name);
        benchmark::RegisterBenchmark(("vm/" + name).c_str(), BM_Vm,
                                     std::make_shared<VmProgram>(entry.name))
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("native/" + name).c_str(), BM_Native, entry)
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    reporter.print_ratios();
    benchmark::Shutdown();
    return 0;
}
