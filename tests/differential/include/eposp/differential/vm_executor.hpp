#pragma once

// The VM as an executor: compile() with the compiler, link for one engine (interpreter or
// compiled), run on a machine with a virtual clock.

#include "eposp/differential/executor.hpp"
#include "eposp/vm/program.hpp"

namespace eposp::differential {

class VmExecutor : public Executor {
public:
    explicit VmExecutor(vm::Engine engine) : engine_(engine) {}
    std::string name() const override;
    Execution run(const std::string& source, int scans) override;

private:
    vm::Engine engine_;
};

} // namespace eposp::differential
