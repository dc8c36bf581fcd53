#include "emit_in_group.hpp"

// Cvt: the conversions between integers and reals that are a few machine instructions.

namespace eposp::vm::jit {

// Integer to integer wraps (sign- or zero-extend, keep the low bytes); integer to real and real
// to real round as the C++ cast does. To or from BOOL, real to integer (rounding, saturating)
// and ULINT to real go through the step function.
template <typename T, typename R>
bool Translator::emit_Cvt(const Instruction& ins) {
    if constexpr (kInteger<T> && kInteger<R>) {
        load64(ins.b, sizeof(T), std::is_signed_v<T>);
        store(ins.a, sizeof(R), rax);
        return true;
    } else if constexpr (kInteger<T> && kFloat<R> && !std::is_same_v<T, std::uint64_t>) {
        load64(ins.b, sizeof(T), std::is_signed_v<T>);
        sizeof(R) == 4 ? cvtsi2ss(xmm0, rax) : cvtsi2sd(xmm0, rax);
        float_store<R>(ins.a);
        return true;
    } else if constexpr (kFloat<T> && kFloat<R>) {
        if constexpr (sizeof(T) == sizeof(R)) {
            float_load<T>(ins.b);
        } else if constexpr (sizeof(T) == 4) {
            cvtss2sd(xmm0, at(ins.b, 4));
        } else {
            cvtsd2ss(xmm0, at(ins.b, 8));
        }
        float_store<R>(ins.a);
        return true;
    } else {
        return false;
    }
}

bool Translator::emit_conversions(const Instruction& ins) {
    return emit_in_group<EmitterGroup::Conversions>(ins);
}

} // namespace eposp::vm::jit
