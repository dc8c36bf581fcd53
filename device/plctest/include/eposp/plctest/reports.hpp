#pragma once

#include "eposp/plctest/test_results.hpp"

#include <string>
#include <vector>

namespace eposp::plctest {

/// The console report: per suite a line with its counts and times, each failure as
/// `file:line: Suite.Test: expected X, got Y: message`, and the closing line
/// `N passed, N failed` (`, N skipped` when any were).
std::string console_report(const std::vector<SuiteResult>& suites);

/// The closing line alone.
std::string totals_line(const Totals& totals);

/// The run as JUnit XML, as Jenkins and GitLab read it: a <testsuite> per suite, a <testcase>
/// per test with `time` in wall seconds and the machine time in its <system-out> and in the
/// suite's <properties>; a suite that could not run is one <testcase> with an <error>.
std::string junit_xml(const std::vector<SuiteResult>& suites);

} // namespace eposp::plctest
