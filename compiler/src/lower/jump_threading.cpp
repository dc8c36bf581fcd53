#include "jump_threading.hpp"

#include "code_rewriter.hpp"

namespace eposp::compiler::lower {

namespace {

/// Where a jump to `target` ends after following unconditional jumps (bounded: a cycle of
/// jumps is never generated, but the bound keeps one from hanging the compiler).
std::uint32_t final_target(const vm::Image& image, std::uint32_t target) {
    for (int hops = 0;
         hops < 16 && target < image.code.size() && image.code[target].opcode == vm::Opcode::Jmp;
         ++hops) {
        target = image.code[target].a;
    }
    return target;
}

} // namespace

void thread_jumps(vm::Image& image) {
    for (vm::Instruction& instruction : image.code) {
        retarget(instruction, image.jump_tables,
                 [&](std::uint32_t target) { return final_target(image, target); });
        // An unconditional jump to a return is the return (no fall-through to preserve).
        if (instruction.opcode == vm::Opcode::Jmp && instruction.a < image.code.size() &&
            image.code[instruction.a].opcode == vm::Opcode::Ret) {
            instruction = image.code[instruction.a];
        }
    }
}

} // namespace eposp::compiler::lower
