#include "context_offsets.hpp"
#include "emit_in_group.hpp"

// Nop, Jmp, Jt, Jf, JtX, JfX and JTab: jumps on a BOOL, on a BOOL element, and through a jump
// table (a CASE).

namespace eposp::vm::jit {

template <typename T, typename R>
bool Translator::emit_Nop(const Instruction&) {
    return true;
}

template <typename T, typename R>
bool Translator::emit_Jmp(const Instruction& ins) {
    charge_block();
    jump_to(ins.a);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Jt(const Instruction& ins) {
    charge_block();
    cmp(at(ins.a, 1), 0);
    branch_if(Cond::NE, ins.b);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Jf(const Instruction& ins) {
    charge_block();
    cmp(at(ins.a, 1), 0);
    branch_if(Cond::E, ins.b);
    return true;
}

template <typename T, typename R>
bool Translator::emit_JtX(const Instruction& ins) {
    const auto address = element(ins, ins.a, ins.b);
    charge_block();
    cmp(byte[address], 0);
    branch_if(Cond::NE, ins.c);
    return true;
}

template <typename T, typename R>
bool Translator::emit_JfX(const Instruction& ins) {
    const auto address = element(ins, ins.a, ins.b);
    charge_block();
    cmp(byte[address], 0);
    branch_if(Cond::E, ins.c);
    return true;
}

// The selector meets the table's low end on the 32-bit circle, as in the interpreter; the
// target is known only at run time, so the jump goes through the entry table.
template <typename T, typename R>
bool Translator::emit_JTab(const Instruction& ins) {
    const JumpTable& table = image_.jump_tables[ins.b];
    charge_block();
    if constexpr (sizeof(T) == 2) {
        std::is_signed_v<T> ? movsx(eax, at(ins.a, 2)) : movzx(eax, at(ins.a, 2));
    } else {
        mov(eax, at(ins.a, 4));
    }
    sub(eax, static_cast<std::uint32_t>(table.low));
    Xbyak::Label outside;
    Xbyak::Label go;
    cmp(eax, static_cast<std::uint32_t>(table.targets.size()));
    jae(outside);
    mov(rdx, reinterpret_cast<std::size_t>(out_.jump_targets_[ins.b].data()));
    mov(ecx, dword[rdx + rax * 4]);
    jmp(go);
    L(outside);
    mov(ecx, ins.c);
    L(go);
    test(rbx, rbx);
    Exit e;
    e.kind = ExitKind::Suspended;
    e.pou = pou_index_;
    e.pc_in_ecx = true;
    js(exit(std::move(e)));
    mov(rdx, qword[r15 + kEntries]);
    jmp(qword[rdx + rcx * 8]);
    return true;
}

bool Translator::emit_jumps(const Instruction& ins) {
    return emit_in_group<EmitterGroup::Jumps>(ins);
}

} // namespace eposp::vm::jit
