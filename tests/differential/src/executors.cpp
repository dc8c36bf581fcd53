#include "eposp/differential/executors.hpp"

#include "eposp/differential/reference_executor.hpp"
#include "eposp/differential/vm_executor.hpp"

namespace eposp::differential {

Executors all_executors() {
    std::vector<std::unique_ptr<Executor>> executors;
    executors.push_back(std::make_unique<VmExecutor>(vm::Engine::Interpreter));
    executors.push_back(std::make_unique<VmExecutor>(vm::Engine::Compiled));
    executors.push_back(std::make_unique<ReferenceExecutor>());
    return Executors(std::move(executors));
}

} // namespace eposp::differential
