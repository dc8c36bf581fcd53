#pragma once

#include "translator.hpp"

// Included by each emit_<group>.cpp, which instantiates it for its own group only: the cases of
// other groups are discarded, so their emitters need not be defined in that file.

namespace eposp::vm::jit {

template <EmitterGroup Group>
bool Translator::emit_in_group(const Instruction& ins) {
    switch (ins.opcode) {
#define EPOSP_JIT_EMIT(name, fam, T1, T2, ...)                                                     \
    case Opcode::name:                                                                             \
        if constexpr (kEmitterGroup<families::fam> == Group) {                                     \
            return emit_##fam<T1, T2>(ins);                                                        \
        }                                                                                          \
        break;
        EPOSP_VM_OPCODES(EPOSP_JIT_EMIT)
#undef EPOSP_JIT_EMIT
    }
    return false;
}

} // namespace eposp::vm::jit
