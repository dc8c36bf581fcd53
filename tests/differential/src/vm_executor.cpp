#include "eposp/differential/vm_executor.hpp"

#include "eposp/compiler/compiler.hpp"
#include "eposp/differential/st_generator.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/symbol_lookup.hpp"

#include <cstring>
#include <span>

namespace eposp::differential {
namespace {

// Generated loops end after a few iterations; a scan that runs this long is a hang.
constexpr std::uint64_t kInstructionsPerScan = 50'000'000;

} // namespace

std::string VmExecutor::name() const {
    return engine_ == vm::Engine::Interpreter ? "interpreter" : "compiled";
}

const CompiledSource& VmExecutor::compiled(const std::string& source) {
    if (cache_->source != source) {
        compiler::SourceManager sources;
        const compiler::FileId file = sources.add("main.st", source);
        compiler::Diagnostics diagnostics;
        cache_->source = source;
        cache_->image = compiler::compile(sources, std::span(&file, 1), diagnostics);
        cache_->errors = compiler::render(diagnostics, sources);
    }
    return *cache_;
}

Execution VmExecutor::run(const std::string& source, int scans) {
    Execution execution;
    std::int64_t now_ns = 0;
    vm::NativeRegistry natives;
    vm::stdlib::register_standard_library(natives);
    vm::stdlib::register_clock(natives, [&now_ns] { return now_ns; });
    const CompiledSource& compiled_source = compiled(source);
    if (!compiled_source.image) {
        execution.errors = compiled_source.errors;
        return execution;
    }
    auto program = vm::link(*compiled_source.image, natives, engine_);
    if (!program) {
        execution.errors = program.error();
        return execution;
    }
    const auto checksum = vm::lookup_variable(program->image(), kChecksumPath);
    if (!checksum) {
        execution.errors = checksum.error();
        return execution;
    }
    execution.loaded = true;
    vm::Machine machine(*program);
    machine.set_budget(0, kInstructionsPerScan);
    for (int scan = 0; scan < scans; ++scan) {
        const auto state = machine.run_cycle(0);
        if (state != vm::RunState::Finished) {
            execution.fault_scan = scan;
            execution.fault =
                state == vm::RunState::Faulted ? machine.describe_fault(0) : "scan did not finish";
            break;
        }
        std::uint64_t value = 0;
        std::memcpy(&value, machine.memory().data() + checksum->offset, sizeof value);
        execution.checksums.push_back(value);
        now_ns += 1'000'000;
    }
    return execution;
}

} // namespace eposp::differential
