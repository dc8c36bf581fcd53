#pragma once

// The differential harness: one program on several executors, Main.checksum compared after
// every scan, and faults compared by scan and line; a program of a seed that they disagree on is
// reduced before it is reported.

#include "eposp/differential/executor.hpp"
#include "eposp/differential/st_generator.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace eposp::differential {

struct Verdict {
    enum class Outcome {
        Agree,    ///< every executor that ran it gave the same checksums and faults
        Disagree, ///< at least two did not
        Invalid,  ///< the VM does not take the program: a generator (or compiler) bug
    };
    Outcome outcome = Outcome::Agree;
    std::vector<std::string> names;
    std::vector<Execution> executions;
    /// Per executor, the index of the first executor that behaved the same (itself if none
    /// before it did); -1 for one that refused the program (the reference evaluator may).
    std::vector<int> classes;

    /// The executors' results, one line each.
    std::string describe() const;
};

/// Runs `source` for `scans` scans on each executor and compares them.
Verdict compare(const std::vector<Executor*>& executors, const std::string& source, int scans);

/// What the executors did with the program of one seed.
struct Finding {
    std::uint64_t seed = 0;
    Verdict verdict;
    std::string program;
    std::string reduced; ///< empty when not reduced

    bool agree() const { return verdict.outcome == Verdict::Outcome::Agree; }
};

/// Generates the program of `seed` (std::mt19937_64 seeded with it) and compares the executors
/// on it; when they disagree (or the VM rejects it) and `reduce` is set, reduces it while they
/// keep disagreeing alike.
Finding check_seed(std::uint64_t seed, const GeneratorOptions& options,
                   const std::vector<Executor*>& executors, int scans, bool reduce);

/// The report of a finding: seed, executors' results, reduced program (or the whole one).
std::string describe(const Finding& finding);

} // namespace eposp::differential
