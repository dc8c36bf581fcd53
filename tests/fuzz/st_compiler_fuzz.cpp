// Structured Text of arbitrary bytes through the whole compiler: parse, resolve, type-check and
// generate code either report diagnostics or give an image; every image the compiler makes
// passes the verifier (link) and runs a few cycles of every task within a watchdog budget
// without crashing the host, compiled code ending every cycle as the interpreter does (state,
// instruction count, memory). Diagnostics always render.

#include "eposp/compiler/compiler.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "fuzz_check.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

namespace {

constexpr std::uint64_t kInstructionsPerCycle = 100'000;
constexpr int kCycles = 3;

const eposp::vm::NativeRegistry& natives() {
    static const auto registry = [] {
        eposp::vm::NativeRegistry r;
        eposp::vm::stdlib::register_standard_library(r);
        eposp::vm::stdlib::register_clock(r, [] { return std::int64_t{0}; });
        return r;
    }();
    return registry;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eposp;
    compiler::SourceManager sources;
    const compiler::FileId file =
        sources.add("fuzz.st", std::string(reinterpret_cast<const char*>(data), size));
    compiler::Diagnostics diagnostics;
    auto image = compiler::compile(sources, std::span(&file, 1), diagnostics);
    compiler::render(diagnostics, sources);
    fuzz::require(image.has_value() != diagnostics.has_errors(),
                  "an image exactly when there are no errors");
    if (!image) {
        return 0;
    }
    auto reference = vm::link(*image, natives(), vm::Engine::Interpreter);
    auto program = vm::link(std::move(*image), natives(), vm::Engine::Compiled);
    fuzz::require(program && reference, "every image the compiler makes passes the verifier");
    vm::Machine machine(*program);
    vm::Machine interpreter(*reference);
    for (std::size_t task = 0; task < program->image().tasks.size(); ++task) {
        machine.set_budget(task, kInstructionsPerCycle);
        interpreter.set_budget(task, kInstructionsPerCycle);
        for (int cycle = 0; cycle < kCycles; ++cycle) {
            const auto state = machine.run_cycle(task);
            fuzz::require(state == interpreter.run_cycle(task) &&
                              machine.task(task).executed == interpreter.task(task).executed,
                          "both engines run a cycle alike");
            fuzz::require(std::ranges::equal(machine.memory(), interpreter.memory()),
                          "both engines leave the same memory");
        }
    }
    return 0;
}
