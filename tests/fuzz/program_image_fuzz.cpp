// A program image (.epx) of arbitrary bytes: read_image and link (which verifies) either refuse
// it with a reason or accept it, and an accepted image runs every task entry for a bounded
// number of instructions without crashing the host: the verifier's promise to the interpreter.
// What is accepted is exactly what write_image produces.

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
    const auto program = load_program(bytes, natives());
    if (!program) {
        return 0;
    }
    const auto rewritten = write_image(program->image());
    eposp::fuzz::require(std::equal(rewritten.begin(), rewritten.end(), bytes.begin(), bytes.end()),
                         "an accepted image is exactly what write_image makes of it");
    Machine machine(*program);
    machine.cold_start();
    for (std::size_t task = 0; task < program->image().tasks.size(); ++task) {
        machine.set_budget(task, kInstructionsPerEntry);
        for (std::size_t entry = 0; entry < program->image().tasks[task].entries.size(); ++entry) {
            machine.start(task, entry);
            machine.run(task, kInstructionsPerEntry);
        }
    }
    return 0;
}
