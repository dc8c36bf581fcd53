#include "back_edge_duplication.hpp"

#include "code_rewriter.hpp"

namespace eposp::compiler::lower {

void duplicate_back_edges(vm::Image& image) {
    rewrite_code(image, [](const CodeBefore& before, vm::Pou&, std::uint32_t i, CodeSink& sink) {
        const vm::Instruction& ins = before.code[i];
        if (ins.opcode == vm::Opcode::Jmp &&
            vm::opcode_info(before.code[ins.a].opcode).name.starts_with("For")) {
            sink.keep(before.code[ins.a]);
            // The back-edge is never a POU's last instruction (that is a Ret or a Jmp).
            sink.keep({vm::Opcode::Jmp, 0, ins.a + 1, 0, 0});
            return;
        }
        sink.keep(ins);
    });
}

} // namespace eposp::compiler::lower
