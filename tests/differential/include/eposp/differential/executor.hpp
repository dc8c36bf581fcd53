#pragma once

// One way of running an ST program (an engine of the VM, the reference evaluator): scan by scan,
// reading Main.checksum after each, so that the differential harness compares them all alike.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace eposp::differential {

/// What running a program for some scans gave.
struct Execution {
    bool loaded = false;
    std::string errors;                   ///< why it did not load (compile, link or refusal)
    std::vector<std::uint64_t> checksums; ///< Main.checksum after each scan that finished
    std::optional<int> fault_scan;        ///< the scan (from 0) that stopped with a fault
    std::string fault;                    ///< its text
};

class Executor {
public:
    virtual ~Executor() = default;
    virtual std::string name() const = 0;
    /// Loads `source` and runs `scans` scans of its first task, the clock advancing 1 ms after
    /// each, as tests/compiler/codegen_harness.hpp's StProgram does.
    virtual Execution run(const std::string& source, int scans) = 0;
    /// Whether not loading a program the VM runs is a refusal to compare (the reference
    /// evaluator does not support everything) rather than a disagreement.
    virtual bool may_refuse() const { return false; }
};

} // namespace eposp::differential
