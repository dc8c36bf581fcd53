#pragma once

#include "eposp/core/result.hpp"
#include "eposp/plctest/suite_runner.hpp"
#include "eposp/plctest/suites.hpp"
#include "eposp/vm/coverage_report.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::plctest {

/// `--filter`: GoogleTest's form, `POSITIVE[-NEGATIVE]`, each a `:`-separated list of globs
/// (`*`, `?`, `[…]`) matched against `Suite.Test`; a test runs when it matches a positive one
/// (all do when there is none) and no negative one.
class TestFilter {
public:
    explicit TestFilter(std::string_view filter = "");
    bool selects(std::string_view suite, std::string_view test) const;
    /// Whether some test of `suite` may be selected (a suite that cannot is not run).
    bool may_select(std::string_view suite) const;

private:
    std::vector<std::string> positive_;
    std::vector<std::string> negative_;
};

struct TestRunOptions {
    std::vector<std::string> paths; ///< the program under test and its test files
    RunSettings settings;
    TestFilter filter;
    /// Suites run at once, each in its own EPOS P on its own thread; the results do not depend
    /// on it.
    unsigned jobs = 1;
    /// The suites start in an order shuffled by this seed (the report keeps the files' order):
    /// each suite has a device of its own, so the results must not change with it.
    std::optional<std::uint64_t> seed;
    /// Sees the diagnostics of each compilation, in the order made (they are not in the
    /// reports otherwise, except as a suite's `does not compile` error).
    DiagnosticsObserver observe_diagnostics;
};

struct TestRun {
    TestSources sources;
    std::vector<SuiteResult> suites; ///< in file and source order
    vm::CoverageReport coverage;     ///< of the files' POUs, merged over the suites, if asked for
};

/// Discovers the suites of the files, compiles each with its harness and runs it; the error
/// says why the files could not be read or parsed.
core::Result<TestRun> run_tests(const TestRunOptions& options);

} // namespace eposp::plctest
