#include "eposp/differential/executors.hpp"

#include "eposp/differential/reference_executor.hpp"
#include "eposp/differential/vm_executor.hpp"

namespace eposp::differential {

Executors all_executors() {
    std::vector<std::unique_ptr<Executor>> executors;
    const auto compiled = std::make_shared<CompiledSource>();
    executors.push_back(std::make_unique<VmExecutor>(vm::Engine::Interpreter, compiled));
    executors.push_back(std::make_unique<VmExecutor>(vm::Engine::Compiled, compiled));
    executors.push_back(std::make_unique<ReferenceExecutor>());
    return Executors(std::move(executors));
}

} // namespace eposp::differential
