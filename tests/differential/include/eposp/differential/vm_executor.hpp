#pragma once

// The VM as an executor: compile() with the compiler, link for one engine (interpreter or
// compiled), run on a machine with a virtual clock.

#include "eposp/differential/executor.hpp"
#include "eposp/vm/image.hpp"
#include "eposp/vm/program.hpp"

#include <memory>
#include <optional>

namespace eposp::differential {

/// The image of the last program compiled, so that executors for both engines compile each
/// program once.
struct CompiledSource {
    std::string source;
    std::optional<vm::Image> image;
    std::string errors;
};

class VmExecutor : public Executor {
public:
    VmExecutor(vm::Engine engine, std::shared_ptr<CompiledSource> cache)
        : engine_(engine), cache_(std::move(cache)) {}
    std::string name() const override;
    Execution run(const std::string& source, int scans) override;

private:
    const CompiledSource& compiled(const std::string& source);

    vm::Engine engine_;
    std::shared_ptr<CompiledSource> cache_;
};

} // namespace eposp::differential
