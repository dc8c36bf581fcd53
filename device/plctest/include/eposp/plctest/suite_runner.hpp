#pragma once

#include "eposp/core/result.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/plctest/suites.hpp"
#include "eposp/plctest/test_results.hpp"
#include "eposp/vm/coverage_report.hpp"
#include "eposp/vm/image.hpp"
#include "eposp/vm/plc_runtime.hpp"

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::plctest {

struct RunSettings {
    /// The machine under the program; without one the EPOS P alone, its internal EPOS2 as
    /// axis 0 at 1 ms SYNC (default_network()).
    std::optional<device::NetworkFile> network;
    /// Machine time a test may take from its first TEST() to TEST_FINISHED().
    core::Duration timeout = std::chrono::seconds(10);
    vm::Engine engine = vm::default_engine();
    /// Record the lines and branches run (on the interpreter).
    bool coverage = false;
    /// Whether a test runs, by suite and test name; null: every test.
    std::function<bool(std::string_view suite, std::string_view test)> selected;
};

/// The one-axis device: the EPOS P with its internal EPOS2 as axis 0, SYNC every 1 ms.
device::NetworkFile default_network();

/// The interval of a suite's task: the network's SYNC period (so that the suite runs in step
/// with the drives' process data), 1 ms without SYNC.
core::Duration test_cycle(const device::NetworkFile& network);

/// The harness of `suite`: a CONFIGURATION with one cyclic task of `cycle` that runs the suite
/// (a PROGRAM, or an instance of the FUNCTION_BLOCK) and then ends the test cycle.
std::string harness_source(const Suite& suite, core::Duration cycle);

/// The image of `suite`: the test files without their CONFIGURATIONs, its harness, the motion
/// and test libraries, its mocks substituted; the error is `does not compile:` and the
/// compiler's diagnostics.
/// With `coverage`, simple IFs keep their branches (CompileOptions::if_conversion) so that
/// both outcomes are counted. `observe`, if set, sees the compiler's diagnostics.
core::Result<vm::Image> build_suite(const TestSources& sources, const Suite& suite,
                                    core::Duration cycle, bool coverage,
                                    const DiagnosticsObserver& observe = {});

struct SuiteRun {
    SuiteResult result;
    vm::CoverageReport coverage;
};

/// Runs the image of `suite` in a fresh EPOS P in virtual time until every test it began has
/// finished (or failed: an assertion, a timeout, a run-time error of its task). Without an
/// image, the suite fails with the error that says why.
SuiteRun run_suite(const TestSources& sources, const Suite& suite, core::Result<vm::Image> image,
                   const RunSettings& settings);

} // namespace eposp::plctest
