// A program image (.epx) of arbitrary bytes: read_image and link (which verifies) either refuse
// it with a reason or accept it, and an accepted image runs every task entry for a bounded
// number of instructions without crashing the host: the verifier's promise to both engines.
// What is accepted is exactly what write_image produces, and compiled code ends every run as
// the interpreter does: the same state, instruction count, fault and memory.

#include "eposp/vm/image_format.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "fuzz_check.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

namespace {

constexpr std::uint64_t kInstructionsPerEntry = 10'000;

const eposp::vm::NativeRegistry& natives() {
    static const auto registry = [] {
        eposp::vm::NativeRegistry r;
        eposp::vm::stdlib::register_standard_library(r);
        return r;
    }();
    return registry;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eposp::vm;
    const std::span<const std::uint8_t> bytes(data, size);
    const auto program = load_program(bytes, natives(), Engine::Compiled);
    if (!program) {
        return 0;
    }
    const auto reference = load_program(bytes, natives(), Engine::Interpreter);
    eposp::fuzz::require(static_cast<bool>(reference), "both engines accept the same images");
    const auto rewritten = write_image(program->image());
    eposp::fuzz::require(std::equal(rewritten.begin(), rewritten.end(), bytes.begin(), bytes.end()),
                         "an accepted image is exactly what write_image makes of it");
    Machine machine(*program);
    Machine interpreter(*reference);
    for (std::size_t task = 0; task < program->image().tasks.size(); ++task) {
        machine.set_budget(task, kInstructionsPerEntry);
        interpreter.set_budget(task, kInstructionsPerEntry);
        for (std::size_t entry = 0; entry < program->image().tasks[task].entries.size(); ++entry) {
            machine.start(task, entry);
            interpreter.start(task, entry);
            const auto state = machine.run(task, kInstructionsPerEntry);
            eposp::fuzz::require(state == interpreter.run(task, kInstructionsPerEntry),
                                 "both engines end a run in the same state");
            const TaskState& a = interpreter.task(task);
            const TaskState& b = machine.task(task);
            eposp::fuzz::require(a.executed == b.executed && a.depth == b.depth,
                                 "both engines count the same instructions");
            eposp::fuzz::require(state != RunState::Faulted ||
                                     (a.fault.trap == b.fault.trap &&
                                      a.fault.instruction == b.fault.instruction &&
                                      a.fault.pou == b.fault.pou),
                                 "both engines stop with the same fault");
            eposp::fuzz::require(std::ranges::equal(machine.memory(), interpreter.memory()),
                                 "both engines leave the same memory");
        }
    }
    return 0;
}
