#include "translator.hpp"

#include "block_formation.hpp"
#include "context_offsets.hpp"

#include <memory>
#include <utility>

// The translation of a whole image: entry and exit code, then every POU block by block, each
// instruction by the emitter of its family's group (translator.hpp) or as a call of its step
// function, then the exits.

namespace eposp::vm::jit {

void Translator::emit_entry_and_exit() {
    // enter(context, address): save the callee-saved registers, load the VM's, jump in.
    for (const auto* r : {&rbx, &rbp, &r12, &r13, &r14, &r15}) {
        push(*r);
    }
    sub(rsp, 8); // the stack 16-byte aligned for step functions
    mov(r15, rdi);
    mov(qword[r15 + kMachineStack], rsp);
    xor_(ebp, ebp);
    mov(r12, qword[r15 + context_base(Base::Static)]);
    mov(r13, qword[r15 + context_base(Base::Frame)]);
    mov(r14, qword[r15 + context_base(Base::Self)]);
    mov(rbx, qword[r15 + kRemaining]);
    jmp(rsi);

    L(exit_common_);
    mov(qword[r15 + kRemaining], rbx);
    mov(qword[r15 + context_base(Base::Frame)], r13);
    mov(qword[r15 + context_base(Base::Self)], r14);
    mov(rsp, qword[r15 + kMachineStack]);
    add(rsp, 8);
    for (const auto* r : {&r15, &r14, &r13, &r12, &rbp, &rbx}) {
        pop(*r);
    }
    ret();
}

void Translator::emit_exits() {
    for (Exit& e : exits_) {
        L(e.label);
        if (e.charge != 0) {
            sub(rbx, static_cast<std::uint32_t>(e.charge));
        }
        if (e.kind == ExitKind::Trapped) {
            if (e.trap_from_step) {
                sub(eax, kStepTrap);
                mov(dword[r15 + kExitTrap], eax);
            } else {
                mov(dword[r15 + kExitTrap], static_cast<std::uint32_t>(e.trap));
            }
        }
        if (e.pc_in_ecx) {
            mov(dword[r15 + kExitPc], ecx);
        } else {
            mov(dword[r15 + kExitPc], e.pc);
        }
        mov(dword[r15 + kExitPou], e.pou);
        mov(dword[r15 + kExitKind], static_cast<std::uint32_t>(e.kind));
        jmp(exit_common_);
    }
}

void Translator::translate() {
    emit_entry_and_exit();
    const std::vector<bool> starts = block_starts(image_);
    for (std::uint32_t p = 0; p < image_.pous.size(); ++p) {
        pou_index_ = p;
        pou_ = &image_.pous[p];
        for (index_ = pou_->code_begin; index_ < pou_->code_end; ++index_) {
            if (starts[index_]) {
                segment_ = index_;
                stored_rax_.reset();
                stored_xmm0_.reset();
            }
            held_rax_ = std::exchange(stored_rax_, std::nullopt);
            held_xmm0_ = std::exchange(stored_xmm0_, std::nullopt);
            L(labels_[index_]);
            const Instruction& ins = image_.code[index_];
            emit_instruction(ins);
            if (!ends_block(ins) && starts[index_ + 1]) {
                charge_block(); // falls into the next block
            }
        }
    }
    emit_exits();
    readyRE();
    out_.enter_ = getCode<CompiledCode::Entry>();
    out_.entries_.assign(image_.code.size(), nullptr);
    for (const Pou& pou : image_.pous) {
        for (auto i = pou.code_begin; i < pou.code_end; ++i) {
            out_.entries_[i] = labels_[i].getAddress();
        }
    }
    labels_.clear();
    exits_.clear();
}

void Translator::emit_instruction(const Instruction& ins) {
    bool emitted = false;
    switch (emitter_group(ins.opcode)) {
    case EmitterGroup::Jumps:
        emitted = emit_jumps(ins);
        break;
    case EmitterGroup::Calls:
        emitted = emit_calls(ins);
        break;
    case EmitterGroup::Moves:
        emitted = emit_moves(ins);
        break;
    case EmitterGroup::Arithmetic:
        emitted = emit_arithmetic(ins);
        break;
    case EmitterGroup::Logic:
        emitted = emit_logic(ins);
        break;
    case EmitterGroup::Comparisons:
        emitted = emit_comparisons(ins);
        break;
    case EmitterGroup::Conversions:
        emitted = emit_conversions(ins);
        break;
    case EmitterGroup::Step:
        break;
    }
    if (emitted) {
        return;
    }
    call_step(ins);
    if (auto target = branch_target(ins)) {
        charge_block();
        branch(*target, [&](Xbyak::Label& skip) {
            cmp(eax, kStepTaken);
            jne(skip);
        });
    }
}

std::shared_ptr<const CompiledCode> compile(const Image& image) {
    std::shared_ptr<CompiledCode> code(new CompiledCode());
    code->code_ = image.code;
    for (const JumpTable& table : image.jump_tables) {
        code->jump_targets_.push_back(table.targets);
    }
    for (const Pou& pou : image.pous) {
        code->frame_sizes_.push_back(pou.frame_size);
    }
    try {
        auto translator = std::make_unique<Translator>(image, *code);
        translator->translate();
        code->generator_ = std::move(translator);
    } catch (const Xbyak::Error&) {
        return nullptr; // e.g. no executable memory: the interpreter runs the program
    }
    return code;
}

} // namespace eposp::vm::jit
