#include "block_formation.hpp"

#include "step_context.hpp"

namespace eposp::vm::jit {

bool ends_block(const Instruction& ins) {
    return branch_target(ins) || step_function(ins.opcode) == nullptr ||
           ins.opcode == Opcode::CallNative;
}

std::vector<bool> block_starts(const Image& image) {
    std::vector<bool> starts(image.code.size() + 1, false);
    for (const Pou& pou : image.pous) {
        starts[pou.code_begin] = true;
    }
    for (std::size_t i = 0; i < image.code.size(); ++i) {
        if (auto target = branch_target(image.code[i])) {
            starts[*target] = true;
        }
        if (ends_block(image.code[i])) {
            starts[i + 1] = true;
        }
    }
    for (const JumpTable& table : image.jump_tables) {
        for (std::uint32_t target : table.targets) {
            starts[target] = true;
        }
    }
    return starts;
}

} // namespace eposp::vm::jit
