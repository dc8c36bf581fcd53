// Structured Text of arbitrary bytes through the whole compiler: parse, resolve, type-check and
// generate code either report diagnostics or give an image; every image the compiler makes
// passes the verifier (link) and runs a few cycles of every task within a watchdog budget
// without crashing the host, compiled code ending every cycle as the interpreter does (state,
// instruction count, memory). Diagnostics always render. Where the reference evaluator
// (tests/reference) supports the program, its first task also runs there, scan by scan, and every
// variable the evaluator knows must hold what the VM holds and a scan fault on both or neither.

#include "eposp/compiler/compiler.hpp"
#include "eposp/reference/reference_program.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"
#include "fuzz_check.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
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

// Arrays are compared by their first elements only: enough to see a wrong store, and bounded.
constexpr std::uint32_t kElementsCompared = 8;

/// The variable at `path` (of type `type`, at `offset`) and everything inside it, on the VM
/// and the reference evaluator; a variable the evaluator does not know is not compared.
void require_same(const eposp::vm::Image& image, const eposp::vm::Machine& machine,
                  const eposp::reference::ReferenceProgram& reference, const std::string& path,
                  std::uint32_t type, std::uint32_t offset) {
    using eposp::vm::TypeKind;
    const auto& descriptor = image.types[type];
    const auto memory = machine.memory().subspan(offset);
    switch (descriptor.kind) {
    case TypeKind::Elementary:
        if (const auto bits = reference.bits(path); bits && descriptor.size <= sizeof *bits) {
            std::uint64_t value = 0;
            std::memcpy(&value, memory.data(), descriptor.size);
            eposp::fuzz::require(value == *bits, "the reference evaluator agrees on each variable");
        }
        break;
    case TypeKind::String:
        if (const auto text = reference.string(path)) {
            const auto held = eposp::vm::stdlib::read_string(memory);
            eposp::fuzz::require(held && *held == *text,
                                 "the reference evaluator agrees on each string");
        }
        break;
    case TypeKind::Array:
        for (std::uint32_t i = 0; i < std::min(descriptor.count, kElementsCompared); ++i) {
            require_same(image, machine, reference,
                         path + "[" +
                             std::to_string(descriptor.lower + static_cast<std::int32_t>(i)) + "]",
                         descriptor.element, offset + i * image.types[descriptor.element].size);
        }
        break;
    case TypeKind::Struct:
        for (const auto& field : descriptor.fields) {
            require_same(image, machine, reference, path + "." + field.name, field.type,
                         offset + field.offset);
        }
        break;
    }
}

/// The first task on the interpreter and on the reference evaluator, cycle by cycle, where the
/// evaluator supports the program and the VM finishes each cycle within the budget (the
/// evaluator has none).
void compare_with_reference(const std::string& source, const eposp::vm::Program& program) {
    using namespace eposp;
    reference::ReferenceProgram reference(source);
    if (!reference.ok() || program.image().tasks.empty()) {
        return;
    }
    vm::Machine machine(program);
    machine.set_budget(0, kInstructionsPerCycle);
    for (int cycle = 0; cycle < kCycles; ++cycle) {
        const auto state = machine.run_cycle(0);
        // The evaluator has neither an instruction budget nor a stack to overflow.
        const auto trap = machine.task(0).fault.trap;
        if (state != vm::RunState::Finished &&
            (state != vm::RunState::Faulted || trap == vm::Trap::BudgetExceeded ||
             trap == vm::Trap::StackOverflow)) {
            return;
        }
        // The fuzz clock stands still at 0: so does the evaluator's.
        const bool finished = reference.scans(1, 0);
        fuzz::require(finished == (state == vm::RunState::Finished),
                      "the reference evaluator faults where the VM does");
        if (!finished) {
            return;
        }
        for (const auto& symbol : program.image().symbols) {
            require_same(program.image(), machine, reference, symbol.path, symbol.type,
                         symbol.offset);
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eposp;
    compiler::SourceManager sources;
    const std::string source(reinterpret_cast<const char*>(data), size);
    const compiler::FileId file = sources.add("fuzz.st", source);
    compiler::Diagnostics diagnostics;
    auto image = compiler::compile(sources, std::span(&file, 1), diagnostics);
    compiler::render(diagnostics, sources);
    fuzz::require(image.has_value() != diagnostics.has_errors(),
                  "an image exactly when there are no errors");
    if (!image) {
        return 0;
    }
    auto interpreted = vm::link(*image, natives(), vm::Engine::Interpreter);
    auto program = vm::link(std::move(*image), natives(), vm::Engine::Compiled);
    fuzz::require(program && interpreted, "every image the compiler makes passes the verifier");
    vm::Machine machine(*program);
    vm::Machine interpreter(*interpreted);
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
    compare_with_reference(source, *interpreted);
    return 0;
}
