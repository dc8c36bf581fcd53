#include "emit_in_group.hpp"

// Add, Sub, Mul, Div, Mod, AddI, Neg and Sqrt on integers (wrapping) and reals (IEEE 754).

namespace eposp::vm::jit {

template <typename T, typename Operation>
bool Translator::float_binary(const Instruction& ins, Operation&& operation) {
    float_load<T>(ins.b);
    operation(xmm0, at(ins.c, sizeof(T)));
    float_store<T>(ins.a);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Add(const Instruction& ins) {
    if constexpr (kFloat<T>) {
        return float_binary<T>(ins, [&](const Xbyak::Xmm& x, const Xbyak::Address& y) {
            sizeof(T) == 4 ? addss(x, y) : addsd(x, y);
        });
    } else {
        return binary<T>(ins, [&](const Xbyak::Reg& x, const auto& y) { add(x, y); });
    }
}

template <typename T, typename R>
bool Translator::emit_Sub(const Instruction& ins) {
    if constexpr (kFloat<T>) {
        return float_binary<T>(ins, [&](const Xbyak::Xmm& x, const Xbyak::Address& y) {
            sizeof(T) == 4 ? subss(x, y) : subsd(x, y);
        });
    } else {
        return binary<T>(ins, [&](const Xbyak::Reg& x, const auto& y) { sub(x, y); });
    }
}

template <typename T, typename R>
bool Translator::emit_Mul(const Instruction& ins) {
    if constexpr (kFloat<T>) {
        return float_binary<T>(ins, [&](const Xbyak::Xmm& x, const Xbyak::Address& y) {
            sizeof(T) == 4 ? mulss(x, y) : mulsd(x, y);
        });
    } else {
        return binary<T>(ins, [&](const Xbyak::Reg& x, const auto& y) { imul(x, y); });
    }
}

// Truncating integer division: /0 traps, MIN / -1 wraps to MIN and MIN MOD -1 is 0 (where x86
// would fault). INT and SINT divide as 32-bit values.
template <typename T>
bool Translator::division(const Instruction& ins, bool remainder) {
    constexpr int bytes = sizeof(T);
    constexpr int wide = bytes == 8 ? 8 : 4;
    load(rax, ins.b, bytes, std::is_signed_v<T>);
    load(rcx, ins.c, bytes, std::is_signed_v<T>);
    test(work(rcx, wide), work(rcx, wide));
    jz(trap_exit(Trap::DivisionByZero));
    Xbyak::Label done;
    if constexpr (std::is_signed_v<T>) {
        Xbyak::Label divide;
        cmp(work(rcx, wide), -1);
        jne(divide);
        remainder ? xor_(eax, eax) : neg(work(rax, wide));
        jmp(done);
        L(divide);
        wide == 8 ? cqo() : cdq();
        idiv(work(rcx, wide));
    } else {
        xor_(edx, edx);
        div(work(rcx, wide));
    }
    if (remainder) {
        mov(work(rax, wide), work(rdx, wide));
    }
    L(done);
    store(ins.a, bytes, rax);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Div(const Instruction& ins) {
    if constexpr (kFloat<T>) {
        return float_binary<T>(ins, [&](const Xbyak::Xmm& x, const Xbyak::Address& y) {
            sizeof(T) == 4 ? divss(x, y) : divsd(x, y);
        });
    } else {
        return division<T>(ins, false);
    }
}

template <typename T, typename R>
bool Translator::emit_Mod(const Instruction& ins) {
    return division<T>(ins, true);
}

template <typename T, typename R>
bool Translator::emit_AddI(const Instruction& ins) {
    return unary<T>(ins, [&](const Xbyak::Reg& x) { add(x, static_cast<std::int32_t>(ins.c)); });
}

template <typename T, typename R>
bool Translator::emit_Neg(const Instruction& ins) {
    if constexpr (kFloat<T>) {
        return false;
    } else {
        return unary<T>(ins, [&](const Xbyak::Reg& x) { neg(x); });
    }
}

template <typename T, typename R>
bool Translator::emit_Sqrt(const Instruction& ins) {
    sizeof(T) == 4 ? sqrtss(xmm0, at(ins.b, 4)) : sqrtsd(xmm0, at(ins.b, 8));
    float_store<T>(ins.a);
    return true;
}

bool Translator::emit_arithmetic(const Instruction& ins) {
    return emit_in_group<EmitterGroup::Arithmetic>(ins);
}

} // namespace eposp::vm::jit
