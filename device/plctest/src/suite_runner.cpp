// One suite in a fresh EPOS P, in virtual time, until its tests are over.

#include "eposp/plctest/suite_runner.hpp"

#include "eposp/device/epos_p.hpp"
#include "eposp/plctest/test_library.hpp"

#include <chrono>
#include <fmt/format.h>

namespace eposp::plctest {
namespace {

// A suite whose tests never end (TEST names made up anew in every cycle) stops here.
constexpr core::Duration kSuiteLimit = std::chrono::hours(1);
// A body that calls TEST() in none of its first cycles is not a suite that can end.
constexpr int kCyclesToFirstTest = 10;

double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// The first faulted task of the program, as the failure of the tests it stopped.
std::optional<Failure> program_fault(const vm::PlcRuntime& runtime, const TestSources& sources) {
    for (std::size_t task = 0; task < runtime.image().tasks.size(); ++task) {
        if (runtime.task_faulted(task)) {
            const vm::Fault& fault = runtime.fault(task);
            const std::string& pou = runtime.image().pous.at(fault.pou).name;
            return Failure{{sources.file_of(pou), fault.line},
                           "run-time error: " + runtime.fault_text(task)};
        }
    }
    return std::nullopt;
}

} // namespace

SuiteRun run_suite(const TestSources& sources, const Suite& suite, core::Result<vm::Image> image,
                   const RunSettings& settings) {
    SuiteRun run;
    SuiteResult& result = run.result;
    result.name = suite.name;
    result.place = suite.place;
    const double wall_started = wall_seconds();
    const auto finish = [&](std::optional<Failure> error) {
        result.error = std::move(error);
        result.wall_seconds = wall_seconds() - wall_started;
        return std::move(run);
    };
    if (!image) {
        return finish(Failure{suite.place, image.error()});
    }
    const device::NetworkFile network = settings.network.value_or(default_network());
    const core::Duration cycle = test_cycle(network);
    // Before the device: the natives the device's program calls refer to it.
    TestRecorder recorder({.timeout = settings.timeout,
                           .selected =
                               [&](std::string_view test) {
                                   return !settings.selected || settings.selected(suite.name, test);
                               },
                           .wall_clock = wall_seconds});
    device::EposPConfig config;
    config.runtime.engine = settings.engine;
    config.runtime.coverage = settings.coverage ? vm::Coverage::Record : vm::Coverage::Off;
    config.external_bit_rate = network.bit_rate;
    config.node_id = network.node_id;
    device::EposP device(std::move(config));
    device.add_network(network);

    TestLibrary::register_natives(
        device.plc().natives(), recorder, device.loop(),
        [&sources](std::string_view pou) { return sources.file_of(pou); }, device.faults());
    if (auto error = device.plc().load(std::move(*image))) {
        return finish(Failure{suite.place, "cannot be loaded: " + error->message});
    }
    if (auto error = device.start_program(vm::StartMode::Cold)) {
        return finish(Failure{suite.place, "cannot start: " + error->message});
    }
    core::EventLoop& loop = device.loop();
    const core::TimePoint started = loop.now();
    std::optional<Failure> error;
    while (!recorder.done()) {
        loop.run_for(cycle);
        const core::Duration elapsed = loop.now() - started;
        if (auto fault = program_fault(device.plc().runtime(), sources)) {
            recorder.stop(*fault, loop.now());
            if (!recorder.began_any()) {
                error = fault;
            }
            break;
        }
        if (!recorder.began_any() && elapsed >= kCyclesToFirstTest * cycle) {
            error = Failure{suite.place, fmt::format("called TEST() in none of its first {} "
                                                     "cycles: a suite's body calls TEST('name') "
                                                     "in every cycle until its test finishes",
                                                     kCyclesToFirstTest)};
            break;
        }
        if (elapsed >= kSuiteLimit) {
            error = Failure{suite.place, fmt::format("still began new tests after {} of machine "
                                                     "time",
                                                     core::format_duration(kSuiteLimit))};
            break;
        }
    }
    result.tests = recorder.results();
    result.machine_time = loop.now() - started;
    if (!error && recorder.misuse()) {
        error = recorder.misuse();
    }
    run.coverage = device.plc().runtime().coverage();
    return finish(std::move(error));
}

} // namespace eposp::plctest
