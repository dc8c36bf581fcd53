#pragma once

#include "eposp/core/time.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace eposp::plctest {

/// A place in the ST sources: the file (as given on the command line) and the line.
struct SourcePlace {
    std::string file{};
    std::uint32_t line = 0;
};

/// One failed assertion, timeout or run-time error, in the words of the report:
/// `expected 5, got 7: the sum`.
struct Failure {
    SourcePlace place{};
    std::string text{};
};

enum class Outcome : std::uint8_t { Passed, Failed, Skipped };

/// One TEST('name') of a suite.
struct TestResult {
    std::string name{};
    SourcePlace place{}; ///< where TEST('name') is called
    Outcome outcome = Outcome::Passed;
    std::vector<Failure> failures{}; ///< in the order they happened; empty unless Failed
    /// From the cycle of its first TEST() call to the one of its TEST_FINISHED().
    core::Duration machine_time{};
    double wall_seconds = 0;
};

/// One suite: an FB or PROGRAM whose body calls TEST(), run in a fresh EPOS P.
struct SuiteResult {
    std::string name{};
    SourcePlace place{};             ///< its declaration
    std::vector<TestResult> tests{}; ///< in the order of their first TEST() call
    /// Why the suite could not run at all (it did not compile, the program did not start):
    /// its tests are then missing and the suite counts as one failure.
    std::optional<Failure> error{};
    core::Duration machine_time{};
    double wall_seconds = 0;
};

/// The totals of a run: the closing line `N passed, N failed[, N skipped]`.
struct Totals {
    std::size_t passed = 0;
    std::size_t failed = 0;
    std::size_t skipped = 0;
};

Totals totals(const std::vector<SuiteResult>& suites);

} // namespace eposp::plctest
