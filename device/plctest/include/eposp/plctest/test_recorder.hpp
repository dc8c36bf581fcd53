#pragma once

#include "eposp/core/time.hpp"
#include "eposp/plctest/test_results.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::plctest {

/// Where the test library is called from: `key` tells call sites apart (a wait keeps its state
/// per call site and test, a failing assertion is reported once per test), `place` is what the
/// report shows.
struct CallSite {
    std::uint64_t key = 0;
    SourcePlace place;
};

/// What one suite's tests did, fed by the test library's functions as the suite's body calls
/// them cycle after cycle (TcUnit's model): TEST('name') makes `name` the current test, the
/// assertions that follow count for it, TEST_FINISHED() ends it. A test that needs many cycles
/// calls TEST_FINISHED() in a later one; until then every TEST('name') call continues it. The
/// suite is over when every test it began has finished.
class TestRecorder {
public:
    struct Settings {
        /// Machine time a test may take from its first TEST() call to TEST_FINISHED().
        core::Duration timeout = std::chrono::seconds(10);
        /// Whether a test (by name) runs; the others are neither run nor reported.
        std::function<bool(std::string_view test)> selected{};
        /// Seconds on the wall clock, only for the report's wall times.
        std::function<double()> wall_clock{};
    };

    explicit TestRecorder(Settings settings);

    /// TEST('name'): TRUE while the test runs (not finished, not disabled, selected). A name
    /// beginning with `disabled_` is reported as skipped and its assertions are ignored.
    bool begin_test(std::string_view name, const CallSite& site, core::TimePoint now);
    /// TEST_FINISHED(): ends the current test; TRUE if it was running.
    bool finish_test(core::TimePoint now);
    /// An assertion of the current test: `passed`, else `describe()` says how it failed
    /// (`expected 5, got 7: the sum`). Returns `passed`.
    bool check(bool passed, const CallSite& site, const std::function<std::string()>& describe);
    /// WAIT_UNTIL(condition, timeout): TRUE from the first cycle `condition` holds on; the test
    /// fails and ends when it does not hold within `timeout` of the first call.
    bool wait_until(bool condition, core::Duration timeout, const CallSite& site,
                    core::TimePoint now);
    /// ADVANCE_TIME(duration): TRUE once `duration` of machine time has passed since the first
    /// call.
    bool advance_time(core::Duration duration, const CallSite& site, core::TimePoint now);
    /// Whether the running test calls from `site` for the first time: an action that must
    /// happen once in a test (a fault injected) although the test's body runs every cycle.
    bool first_call(const CallSite& site);
    /// Fails the running test (a fault the library could not inject: its reason).
    void fail_running(const CallSite& site, std::string text);
    /// Ends a cycle of the suite's task: a test past its timeout fails and ends.
    void end_cycle(core::TimePoint now);
    /// The suite's task stopped (a run-time error): every running test fails with `failure`.
    void stop(const Failure& failure, core::TimePoint now);

    /// Whether TEST() was called and no test is running any more.
    bool done() const;
    /// Whether TEST() was called at all (a test filtered out counts).
    bool began_any() const { return began_any_; }
    std::vector<TestResult> results() const;
    /// The first misuse of the library: an assertion outside a test, a test name used twice.
    const std::optional<Failure>& misuse() const { return misuse_; }

private:
    struct Test {
        TestResult result;
        core::TimePoint started;
        double wall_started = 0;
        bool running = true;
        std::uint64_t last_cycle = 0;
        std::map<std::uint64_t, core::TimePoint> waits; ///< call site → first call
        std::vector<std::uint64_t> failed_sites;
        std::vector<std::uint64_t> called_sites; ///< first_call()
    };

    Test* running_test();
    void fail(Test& test, Failure failure);
    void end(Test& test, core::TimePoint now);
    void report_misuse(const SourcePlace& place, std::string text);
    double wall_now() const;

    Settings settings_;
    std::vector<Test> tests_;
    std::optional<std::size_t> current_;
    std::uint64_t cycle_ = 0;
    bool outside_tests_ = true; ///< no TEST() call yet in this cycle
    bool began_any_ = false;
    std::optional<Failure> misuse_;
};

/// `T#1s500ms`: a duration as an ST literal.
std::string time_literal(core::Duration duration);

} // namespace eposp::plctest
