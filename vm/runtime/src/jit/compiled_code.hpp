#pragma once

#include "eposp/vm/image.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/task_state.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace Xbyak {
class CodeGenerator;
}

namespace eposp::vm::jit {

struct JitContext;

/// A verified image translated to x86-64 machine code: every instruction has an address, so a
/// task can start or resume at any instruction a suspended run saved. Runs exactly as the
/// interpreter does (the same instruction counts, safe points, traps and activations); only
/// the speed differs.
class CompiledCode {
public:
    ~CompiledCode();

    /// The interpreter's `execute`, in machine code.
    RunState run(const Program& program, std::span<std::uint8_t> memory, TaskState& task,
                 std::uint64_t slice) const;

private:
    friend class Translator;
    friend std::shared_ptr<const CompiledCode> compile(const Image& image);
    CompiledCode() = default;

    using Entry = void (*)(JitContext* context, const void* address);

    std::unique_ptr<Xbyak::CodeGenerator> generator_; ///< owns the executable memory
    std::vector<Instruction> code_; ///< what step functions read, at addresses fixed in the code
    std::vector<std::vector<std::uint32_t>> jump_targets_; ///< of each jump table, likewise
    std::vector<const void*> entries_;                     ///< machine address per instruction
    std::vector<std::uint32_t> frame_sizes_;               ///< per POU
    Entry enter_ = nullptr;
};

/// Translates a verified image; nullptr where this machine has no translator (not x86-64).
std::shared_ptr<const CompiledCode> compile(const Image& image);

} // namespace eposp::vm::jit
