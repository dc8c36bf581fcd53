#pragma once

// Every executor the differential harness compares: the interpreter (the VM's reference
// engine), the compiled engine, and the reference evaluator.

#include "eposp/differential/executor.hpp"

#include <memory>
#include <vector>

namespace eposp::differential {

class Executors {
public:
    explicit Executors(std::vector<std::unique_ptr<Executor>> executors)
        : executors_(std::move(executors)) {}
    std::vector<Executor*> pointers() const {
        std::vector<Executor*> out;
        for (const auto& executor : executors_) {
            out.push_back(executor.get());
        }
        return out;
    }

private:
    std::vector<std::unique_ptr<Executor>> executors_;
};

/// The interpreter first (the others are compared with it), then the compiled engine and the
/// reference evaluator.
Executors all_executors();

} // namespace eposp::differential
