#include "emit_in_group.hpp"

// Eq, Ne, Lt, Le as a BOOL, their compare-and-branch forms JEq, JNe, JLt, JLe, the bit tests
// JTst and JNTst, and For, the back-edge of a FOR loop.

namespace eposp::vm::jit {

template <typename T>
Translator::Cond Translator::compare(std::uint32_t x, std::uint32_t y, Cond signed_cond,
                                     Cond unsigned_cond) {
    constexpr int bytes = sizeof(T);
    constexpr bool sign = std::is_signed_v<T>;
    load(rax, x, bytes, sign);
    if constexpr (bytes >= 4) {
        cmp(work(rax, bytes), at(y, bytes));
    } else {
        load(rcx, y, bytes, sign);
        cmp(eax, ecx);
    }
    return sign ? signed_cond : unsigned_cond;
}

template <typename T>
bool Translator::set_compare(const Instruction& ins, Cond signed_cond, Cond unsigned_cond) {
    if constexpr (kFloat<T>) {
        // x < y is y > x, false when unordered (the carry flag is set then).
        float_load<T>(ins.c);
        sizeof(T) == 4 ? ucomiss(xmm0, at(ins.b, 4)) : ucomisd(xmm0, at(ins.b, 8));
        set_if(unsigned_cond == Cond::B ? Cond::A : Cond::AE, al);
    } else {
        set_if(compare<T>(ins.b, ins.c, signed_cond, unsigned_cond), al);
    }
    mov(at(ins.a, 1), al);
    return true;
}

template <typename T>
bool Translator::branch_compare(const Instruction& ins, Cond signed_cond, Cond unsigned_cond) {
    charge_block();
    if constexpr (kFloat<T>) {
        float_load<T>(ins.b);
        sizeof(T) == 4 ? ucomiss(xmm0, at(ins.a, 4)) : ucomisd(xmm0, at(ins.a, 8));
        branch_if(unsigned_cond == Cond::B ? Cond::A : Cond::AE, ins.c);
    } else {
        branch_if(compare<T>(ins.a, ins.b, signed_cond, unsigned_cond), ins.c);
    }
    return true;
}

// IEEE equality: equal and ordered (an unordered compare sets the parity flag).
template <typename T>
bool Translator::set_float_equality(const Instruction& ins, bool equal) {
    float_load<T>(ins.b);
    sizeof(T) == 4 ? ucomiss(xmm0, at(ins.c, 4)) : ucomisd(xmm0, at(ins.c, 8));
    if (equal) {
        sete(al);
        setnp(cl);
        and_(al, cl);
    } else {
        setne(al);
        setp(cl);
        or_(al, cl);
    }
    mov(at(ins.a, 1), al);
    return true;
}

template <typename T>
bool Translator::branch_float_equality(const Instruction& ins, bool equal) {
    charge_block();
    float_load<T>(ins.a);
    sizeof(T) == 4 ? ucomiss(xmm0, at(ins.b, 4)) : ucomisd(xmm0, at(ins.b, 8));
    branch(ins.c, [&](Xbyak::Label& skip) {
        if (equal) {
            jne(skip);
            jp(skip);
        } else {
            Xbyak::Label taken;
            jp(taken);
            je(skip);
            L(taken);
        }
    });
    return true;
}

template <typename T>
bool Translator::equality(const Instruction& ins, bool equal, bool branches) {
    if constexpr (kFloat<T>) {
        return branches ? branch_float_equality<T>(ins, equal) : set_float_equality<T>(ins, equal);
    } else {
        const Cond cond = equal ? Cond::E : Cond::NE;
        return branches ? branch_compare<T>(ins, cond, cond) : set_compare<T>(ins, cond, cond);
    }
}

template <typename T, typename R>
bool Translator::emit_Eq(const Instruction& ins) {
    return equality<T>(ins, true, false);
}

template <typename T, typename R>
bool Translator::emit_Ne(const Instruction& ins) {
    return equality<T>(ins, false, false);
}

template <typename T, typename R>
bool Translator::emit_Lt(const Instruction& ins) {
    return set_compare<T>(ins, Cond::L, Cond::B);
}

template <typename T, typename R>
bool Translator::emit_Le(const Instruction& ins) {
    return set_compare<T>(ins, Cond::LE, Cond::BE);
}

template <typename T, typename R>
bool Translator::emit_JEq(const Instruction& ins) {
    return equality<T>(ins, true, true);
}

template <typename T, typename R>
bool Translator::emit_JNe(const Instruction& ins) {
    return equality<T>(ins, false, true);
}

template <typename T, typename R>
bool Translator::emit_JLt(const Instruction& ins) {
    return branch_compare<T>(ins, Cond::L, Cond::B);
}

template <typename T, typename R>
bool Translator::emit_JLe(const Instruction& ins) {
    return branch_compare<T>(ins, Cond::LE, Cond::BE);
}

template <typename T>
bool Translator::bit_test_branch(const Instruction& ins, bool when_set) {
    charge_block();
    load(rax, ins.a, sizeof(T), false);
    load(rcx, ins.b, sizeof(T), false);
    test(work(rax, sizeof(T)), work(rcx, sizeof(T)));
    branch_if(when_set ? Cond::NE : Cond::E, ins.c);
    return true;
}

template <typename T, typename R>
bool Translator::emit_JTst(const Instruction& ins) {
    return bit_test_branch<T>(ins, true);
}

template <typename T, typename R>
bool Translator::emit_JNTst(const Instruction& ins) {
    return bit_test_branch<T>(ins, false);
}

// [A] += step, then loop while [A] <= [B] (step > 0) or [A] >= [B], compared as T, and the
// addition did not wrap around T (a loop up to T's greatest value ends there).
template <typename T, typename R>
bool Translator::emit_For(const Instruction& ins) {
    constexpr int bytes = sizeof(T);
    const auto step = static_cast<std::int16_t>(ins.aux);
    charge_block();
    load(rax, ins.a, bytes, false);
    add(part(rax, bytes), step); // at T's width, so that its flags tell whether it wrapped
    store(ins.a, bytes, rax);
    branch(ins.c, [&](Xbyak::Label& skip) {
        // The flags of the addition: overflow for a signed T; for an unsigned
        // one a carry adding a positive step, none adding a negative (two's complement) one.
        if constexpr (std::is_signed_v<T>) {
            jo(skip);
        } else if (step > 0) {
            jc(skip);
        } else {
            jnc(skip);
        }
        const Cond cond = compare<T>(ins.a, ins.b, step > 0 ? Cond::LE : Cond::GE,
                                     step > 0 ? Cond::BE : Cond::AE);
        jump_if(negate(cond), skip);
    });
    return true;
}

bool Translator::emit_comparisons(const Instruction& ins) {
    return emit_in_group<EmitterGroup::Comparisons>(ins);
}

} // namespace eposp::vm::jit
