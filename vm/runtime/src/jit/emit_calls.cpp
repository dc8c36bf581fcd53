#include "context_offsets.hpp"
#include "emit_in_group.hpp"

// Call, CallFb, CallFbP, CallNative and Ret: a VM call is a machine call, with the activation on
// the task's call stack as well.

namespace eposp::vm::jit {

// Enters `callee` with its frame where this POU's out area is and `rsi` as its self, after the
// interpreter's checks: call depth and stack space.
void Translator::enter(std::uint32_t callee_index) {
    const Pou& callee = image_.pous[callee_index];
    mov(rdi, qword[r15 + kDepth]);
    mov(eax, dword[rdi]);
    cmp(eax, kMaxCallDepth);
    je(trap_exit(Trap::StackOverflow));
    lea(rdx, ptr[r13 + pou_->frame_size]);
    mov(rcx, rdx);
    sub(rcx, r12);
    add(rcx, std::uint32_t{callee.frame_size} + callee.out_size);
    cmp(rcx, qword[r15 + kStackEnd]);
    ja(trap_exit(Trap::StackOverflow));
    // calls[depth++] = {return pc, this POU, frame, self}
    mov(r9, qword[r15 + kCalls]);
    mov(ecx, eax);
    shl(rcx, 4);
    add(r9, rcx);
    mov(dword[r9], index_ + 1);
    mov(dword[r9 + 4], pou_index_);
    mov(rcx, r13);
    sub(rcx, r12);
    mov(dword[r9 + 8], ecx);
    mov(rcx, r14);
    sub(rcx, r12);
    mov(dword[r9 + 12], ecx);
    inc(eax);
    mov(dword[rdi], eax);
    mov(r13, rdx);
    mov(r14, rsi);
    mov(qword[r15 + context_base(Base::Frame)], r13);
    mov(qword[r15 + context_base(Base::Self)], r14);
    lea(rax, ptr[r13 + callee.frame_size]);
    mov(qword[r15 + context_base(Base::Out)], rax);
    charge_block();
    js(suspend_exit(callee.code_begin, callee_index));
    // 16 bytes a call, the return address included: step functions need the stack aligned.
    inc(ebp);
    sub(rsp, 8);
    call(labels_[callee.code_begin]);
    add(rsp, 8); // the return lands here, then goes on at the next instruction
}

template <typename T, typename R>
bool Translator::emit_Call(const Instruction& ins) {
    mov(rsi, r14);
    enter(ins.a);
    return true;
}

template <typename T, typename R>
bool Translator::emit_CallFb(const Instruction& ins) {
    lea(rsi, ptr[address_of(ins.a)]);
    enter(ins.b);
    return true;
}

// The instance pointer is checked as Ldp checks a pointer: not NULL, the instance in memory.
template <typename T, typename R>
bool Translator::emit_CallFbP(const Instruction& ins) {
    mov(rax, at(ins.a, 8));
    cmp(rax, kNullGuardSize);
    jb(trap_exit(Trap::NullDereference));
    mov(rcx, qword[r15 + kMemSize]);
    cmp(rax, rcx);
    ja(trap_exit(Trap::InvalidAddress));
    sub(rcx, rax);
    cmp(rcx, image_.pous[ins.b].instance_size);
    jb(trap_exit(Trap::InvalidAddress));
    lea(rsi, ptr[r12 + rax]);
    enter(ins.b);
    return true;
}

template <typename T, typename R>
bool Translator::emit_CallNative(const Instruction& ins) {
    call_step(ins);
    charge_block();
    js(suspend_exit(index_ + 1, pou_index_));
    return true;
}

template <typename T, typename R>
bool Translator::emit_Ret(const Instruction&) {
    charge_block();
    mov(rdi, qword[r15 + kDepth]);
    mov(eax, dword[rdi]);
    test(eax, eax);
    Exit finished;
    finished.kind = ExitKind::Finished;
    je(exit(std::move(finished)));
    dec(eax);
    mov(dword[rdi], eax);
    mov(r9, qword[r15 + kCalls]);
    shl(rax, 4);
    add(r9, rax);
    mov(eax, dword[r9 + 8]);
    lea(r13, ptr[r12 + rax]);
    mov(eax, dword[r9 + 12]);
    lea(r14, ptr[r12 + rax]);
    mov(qword[r15 + context_base(Base::Frame)], r13);
    mov(qword[r15 + context_base(Base::Self)], r14);
    mov(eax, dword[r9 + 4]);
    mov(rdx, qword[r15 + kFrameSizes]);
    mov(eax, dword[rdx + rax * 4]);
    add(rax, r13);
    mov(qword[r15 + context_base(Base::Out)], rax);
    Xbyak::Label entered_before;
    test(ebp, ebp);
    jz(entered_before);
    dec(ebp);
    ret();
    L(entered_before);
    mov(eax, dword[r9]);
    mov(rdx, qword[r15 + kEntries]);
    jmp(qword[rdx + rax * 8]);
    return true;
}

bool Translator::emit_calls(const Instruction& ins) {
    return emit_in_group<EmitterGroup::Calls>(ins);
}

} // namespace eposp::vm::jit
