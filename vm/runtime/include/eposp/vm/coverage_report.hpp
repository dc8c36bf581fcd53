#pragma once

#include <compare>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace eposp::vm {

/// A conditional branch point of a POU: the `block`-th one (from 0, in code order) on its
/// source line. Stable across compiles of the same source, so reports of runs merge.
struct BranchPoint {
    std::uint32_t line = 0;
    std::uint32_t block = 0;
    auto operator<=>(const BranchPoint&) const = default;
};

/// What the tests executed of one POU (its inlined copies included).
struct PouCoverage {
    /// How often the POU was entered: called, run by a task, or its body inlined and reached.
    std::uint64_t calls = 0;
    /// Every source line with code, and how often it was executed.
    std::map<std::uint32_t, std::uint64_t> lines;
    /// How often each outcome of a branch point was taken: a conditional jump (IF, WHILE,
    /// FOR, a CASE label compared) has {jumped, fell through}; a CASE's jump table has one
    /// outcome per table entry and the last for a selector past its end.
    std::map<BranchPoint, std::vector<std::uint64_t>> branches;

    std::size_t lines_hit() const;
    std::size_t branch_outcomes() const;
    std::size_t branch_outcomes_taken() const;
    bool operator==(const PouCoverage&) const = default;
};

/// Line and branch coverage by POU name (PlcRuntime::coverage, docs/runtime.md "Coverage").
struct CoverageReport {
    std::map<std::string, PouCoverage> pous;

    /// Adds the counts of `other` (another run, maybe of another compile of the same source).
    void merge(const CoverageReport& other);
    bool operator==(const CoverageReport&) const = default;
};

/// One line per POU for a console: `Main: lines 12/14 (85.7%), branches 5/8`, where the
/// branches are outcomes taken at least once of all outcomes.
std::string coverage_summary(const CoverageReport& report);

} // namespace eposp::vm
