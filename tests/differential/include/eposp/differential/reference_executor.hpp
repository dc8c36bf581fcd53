#pragma once

// The reference evaluator (tests/reference) as an executor. It may refuse a program that uses
// something it does not support; the harness then compares the other executors only.

#include "eposp/differential/executor.hpp"

namespace eposp::differential {

class ReferenceExecutor : public Executor {
public:
    std::string name() const override { return "reference"; }
    Execution run(const std::string& source, int scans) override;
    bool may_refuse() const override { return true; }
};

} // namespace eposp::differential
