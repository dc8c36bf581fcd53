// Structured Text of arbitrary bytes through the whole compiler: parse, resolve, type-check and
// generate code either report diagnostics or give an image; every image the compiler makes
// passes the verifier (link) and runs a few cycles of every task within a watchdog budget
// without crashing the host. Diagnostics always render.

#include "eposp/compiler/compiler.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "fuzz_check.hpp"

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
    auto program = vm::link(std::move(*image), natives());
    fuzz::require(static_cast<bool>(program), "every image the compiler makes passes the verifier");
    vm::Machine machine(*program);
    for (std::size_t task = 0; task < program->image().tasks.size(); ++task) {
        machine.set_budget(task, kInstructionsPerCycle);
        for (int cycle = 0; cycle < kCycles; ++cycle) {
            machine.run_cycle(task);
        }
    }
    return 0;
}
