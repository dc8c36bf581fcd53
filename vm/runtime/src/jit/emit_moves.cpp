#include "context_offsets.hpp"
#include "emit_in_group.hpp"

#include <cstdint>

// Mov, Ldi, Ldx, Stx, Ldp, Stp and CMov: moves, indexed and pointer loads and stores with their
// checks, and the conditional move.

namespace eposp::vm::jit {

template <typename T, typename R>
bool Translator::emit_Mov(const Instruction& ins) {
    load(rax, ins.b, sizeof(T), false);
    store(ins.a, sizeof(T), rax);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Ldi(const Instruction& ins) {
    const std::uint64_t value = std::uint64_t{ins.b} | std::uint64_t{ins.c} << 32;
    if constexpr (sizeof(T) == 8) {
        mov(rax, value);
        mov(at(ins.a, 8), rax);
    } else {
        mov(at(ins.a, sizeof(T)), static_cast<std::uint32_t>(static_cast<T>(value)));
    }
    return true;
}

template <typename T, typename R>
bool Translator::emit_Ldx(const Instruction& ins) {
    const auto address = element(ins, ins.b, ins.c);
    if constexpr (sizeof(T) < 4) {
        movzx(ecx, sized(sizeof(T))[address]);
    } else {
        mov(work(rcx, sizeof(T)), sized(sizeof(T))[address]);
    }
    store(ins.a, sizeof(T), rcx);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Stx(const Instruction& ins) {
    load(rcx, ins.c, sizeof(T), false);
    const auto address = element(ins, ins.a, ins.b);
    mov(sized(sizeof(T))[address], part(rcx, sizeof(T)));
    return true;
}

void Translator::checked_pointer(std::uint32_t pointer_field, std::uint32_t offset,
                                 std::uint32_t bytes) {
    held_rax_.reset();
    mov(rax, at(pointer_field, 8));
    cmp(rax, kNullGuardSize);
    jb(trap_exit(Trap::NullDereference));
    mov(rcx, qword[r15 + kMemSize]);
    cmp(rax, rcx);
    ja(trap_exit(Trap::InvalidAddress));
    sub(rcx, rax);
    mov(rdx, std::uint64_t{offset} + bytes);
    cmp(rcx, rdx);
    jb(trap_exit(Trap::InvalidAddress));
}

// A displacement holds 31 bits: a larger offset goes through the step function.
template <typename T, typename R>
bool Translator::emit_Ldp(const Instruction& ins) {
    if (ins.c > INT32_MAX) {
        return false;
    }
    checked_pointer(ins.b, ins.c, sizeof(T));
    const auto source = sized(sizeof(T))[r12 + rax + ins.c];
    if constexpr (sizeof(T) < 4) {
        movzx(ecx, source);
    } else {
        mov(work(rcx, sizeof(T)), source);
    }
    store(ins.a, sizeof(T), rcx);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Stp(const Instruction& ins) {
    if (ins.c > INT32_MAX) {
        return false;
    }
    checked_pointer(ins.a, ins.c, sizeof(T));
    load(rcx, ins.b, sizeof(T), false);
    mov(sized(sizeof(T))[r12 + rax + ins.c], part(rcx, sizeof(T)));
    return true;
}

// The destination is rewritten either way, with its own value when the condition is FALSE.
template <typename T, typename R>
bool Translator::emit_CMov(const Instruction& ins) {
    constexpr int bytes = sizeof(T);
    load(rax, ins.a, bytes, false);
    load(rcx, ins.c, bytes, false);
    cmp(at(ins.b, 1), 0);
    cmovne(work(rax, bytes), work(rcx, bytes));
    store(ins.a, bytes, rax);
    return true;
}

bool Translator::emit_moves(const Instruction& ins) {
    return emit_in_group<EmitterGroup::Moves>(ins);
}

} // namespace eposp::vm::jit
