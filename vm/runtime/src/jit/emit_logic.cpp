#include "emit_in_group.hpp"

// NotB, Not, And, Or, Xor, Shl and Shr: the logical and bitwise operations and the shifts.

namespace eposp::vm::jit {

template <typename T, typename R>
bool Translator::emit_NotB(const Instruction& ins) {
    cmp(at(ins.b, 1), 0);
    sete(al);
    mov(at(ins.a, 1), al);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Not(const Instruction& ins) {
    return unary<T>(ins, [&](const Xbyak::Reg& x) { not_(x); });
}

template <typename T, typename R>
bool Translator::emit_And(const Instruction& ins) {
    return binary<T>(ins, [&](const Xbyak::Reg& x, const auto& y) { and_(x, y); });
}

template <typename T, typename R>
bool Translator::emit_Or(const Instruction& ins) {
    return binary<T>(ins, [&](const Xbyak::Reg& x, const auto& y) { or_(x, y); });
}

template <typename T, typename R>
bool Translator::emit_Xor(const Instruction& ins) {
    return binary<T>(ins, [&](const Xbyak::Reg& x, const auto& y) { xor_(x, y); });
}

// A count of the width or more gives 0; x86 would take the count modulo 32 or 64.
template <typename T>
bool Translator::shift(const Instruction& ins, bool left) {
    constexpr int bytes = sizeof(T);
    mov(ecx, at(ins.c, 4));
    load(rax, ins.b, bytes, false);
    left ? shl(work(rax, bytes), cl) : shr(work(rax, bytes), cl);
    xor_(edx, edx);
    cmp(ecx, bytes * 8);
    cmovae(work(rax, bytes), work(rdx, bytes));
    store(ins.a, bytes, rax);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Shl(const Instruction& ins) {
    return shift<T>(ins, true);
}

template <typename T, typename R>
bool Translator::emit_Shr(const Instruction& ins) {
    return shift<T>(ins, false);
}

bool Translator::emit_logic(const Instruction& ins) {
    return emit_in_group<EmitterGroup::Logic>(ins);
}

} // namespace eposp::vm::jit
