#pragma once

#include "eposp/vm/image.hpp"
#include "eposp/vm/instruction.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/task_state.hpp"
#include "eposp/vm/value_semantics.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

// What each instruction does, once for both engines: the interpreter's handlers and the
// compiled code's step functions expand these family macros (VM_EXEC_<family>) per type of the
// opcode list. An engine defines how control leaves an instruction (VM_NEXT, VM_BRANCH_IF,
// VM_TRAP) and the names the macros read: `ip`, `base` (one pointer per Base), `arrays`, `mem`
// and `mem_size`. The families that change the activation (Jmp, JTab, calls, Ret) are each
// engine's own.

namespace eposp::vm::detail {

template <typename T>
inline T load(const std::uint8_t* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return value;
}

template <typename T>
inline void store(std::uint8_t* p, T value) {
    std::memcpy(p, &value, sizeof(T));
}

// An INT index is sign-extended, so both widths meet lower on the same 32-bit circle.
inline std::uint32_t array_index(const ArrayDescriptor& descriptor, const std::uint8_t* index) {
    return descriptor.index_size == 2
               ? static_cast<std::uint32_t>(std::int32_t{load<std::int16_t>(index)})
               : load<std::uint32_t>(index);
}

// A native call's arguments object lives here, not in a handler: no object with a destructor
// may be in scope where an interpreter handler leaves by computed goto.
// `task` and `instruction` say where the call is, read only if the host asks for its call site.
inline bool call_native(const Program& program, std::uint32_t import, std::uint8_t* block,
                        std::span<std::uint8_t> memory, TaskState& task,
                        std::uint32_t instruction) {
    const NativeCallContext context{&program.image(), task.calls.data(), task.depth, instruction};
    NativeArgs args(block, program.image().imports[import].signature, memory, &context);
    program.native(import)(args);
    if (args.failed()) {
        task.fault.native_reason = args.failure();
        return false;
    }
    return true;
}

} // namespace eposp::vm::detail

#define VM_OPERAND(field) (base[(field) >> kBaseShift] + ((field)&kOffsetMask))
#define A VM_OPERAND(ip->a)
#define B VM_OPERAND(ip->b)
#define C VM_OPERAND(ip->c)
// Checked element address: index - lower, modulo 2^32, must be below the descriptor's count.
#define VM_ELEMENT(array, index_operand, out)                                                      \
    const auto& descriptor = arrays[ip->aux];                                                      \
    const auto element =                                                                           \
        array_index(descriptor, index_operand) - static_cast<std::uint32_t>(descriptor.lower);     \
    if (element >= descriptor.count) {                                                             \
        VM_TRAP(Trap::IndexOutOfRange);                                                            \
    }                                                                                              \
    out = std::uint64_t{element} * descriptor.element_size + descriptor.offset
// Checked pointer: not NULL (or into the guard) and `size` bytes at pointer+offset in memory.
#define VM_DEREF(pointer_operand, offset, size, out)                                               \
    const auto address = load<std::uint64_t>(pointer_operand);                                     \
    if (address < kNullGuardSize) {                                                                \
        VM_TRAP(Trap::NullDereference);                                                            \
    }                                                                                              \
    if (address > mem_size || std::uint64_t{offset} + (size) > mem_size - address) {               \
        VM_TRAP(Trap::InvalidAddress);                                                             \
    }                                                                                              \
    out = mem + address + (offset)
// Enters `callee` with its frame where the caller's out area is (the arguments already there).

#define VM_EXEC_Jt(T1, T2) VM_BRANCH_IF(load<std::uint8_t>(A) != 0, ip->b);
#define VM_EXEC_Jf(T1, T2) VM_BRANCH_IF(load<std::uint8_t>(A) == 0, ip->b);
#define VM_EXEC_JtX(T1, T2)                                                                        \
    {                                                                                              \
        std::uint64_t at;                                                                          \
        VM_ELEMENT(A, B, at);                                                                      \
        VM_BRANCH_IF(load<std::uint8_t>(A + at) != 0, ip->c);                                      \
    }
#define VM_EXEC_JfX(T1, T2)                                                                        \
    {                                                                                              \
        std::uint64_t at;                                                                          \
        VM_ELEMENT(A, B, at);                                                                      \
        VM_BRANCH_IF(load<std::uint8_t>(A + at) == 0, ip->c);                                      \
    }
// The selector, sign- or zero-extended as its type says, meets `low` on the 32-bit circle.
#define VM_EXEC_MovN(T1, T2)                                                                       \
    std::memmove(A, B, ip->c);                                                                     \
    VM_NEXT();
#define VM_EXEC_Addr(T1, T2)                                                                       \
    store<std::uint64_t>(A, static_cast<std::uint64_t>(B - mem));                                  \
    VM_NEXT();
#define VM_EXEC_IdxA(T1, T2)                                                                       \
    {                                                                                              \
        std::uint64_t at;                                                                          \
        VM_ELEMENT(B, C, at);                                                                      \
        store<std::uint64_t>(A, static_cast<std::uint64_t>(B - mem) + at);                         \
        VM_NEXT();                                                                                 \
    }
// A NULL array pointer plus an index can point past the NULL guard: refuse it here.
#define VM_EXEC_IdxAP(T1, T2)                                                                      \
    {                                                                                              \
        std::uint64_t at;                                                                          \
        VM_ELEMENT(B, C, at);                                                                      \
        const auto array_address = load<std::uint64_t>(B);                                         \
        if (array_address < kNullGuardSize) {                                                      \
            VM_TRAP(Trap::NullDereference);                                                        \
        }                                                                                          \
        store<std::uint64_t>(A, array_address + at);                                               \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_LdpN(T1, T2)                                                                       \
    {                                                                                              \
        std::uint8_t* source;                                                                      \
        VM_DEREF(B, 0, ip->c, source);                                                             \
        std::memmove(A, source, ip->c);                                                            \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_StpN(T1, T2)                                                                       \
    {                                                                                              \
        std::uint8_t* target;                                                                      \
        VM_DEREF(A, 0, ip->c, target);                                                             \
        std::memmove(target, B, ip->c);                                                            \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_NotB(T1, T2)                                                                       \
    store<std::uint8_t>(A, load<std::uint8_t>(B) == 0 ? 1 : 0);                                    \
    VM_NEXT();
#define VM_EXEC_Mov(T, T2)                                                                         \
    store<T>(A, load<T>(B));                                                                       \
    VM_NEXT();
#define VM_EXEC_Ldi(T, T2)                                                                         \
    store<T>(A, static_cast<T>(std::uint64_t{ip->b} | std::uint64_t{ip->c} << 32));                \
    VM_NEXT();
#define VM_EXEC_Ldx(T, T2)                                                                         \
    {                                                                                              \
        std::uint64_t at;                                                                          \
        VM_ELEMENT(B, C, at);                                                                      \
        store<T>(A, load<T>(B + at));                                                              \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_Stx(T, T2)                                                                         \
    {                                                                                              \
        std::uint64_t at;                                                                          \
        VM_ELEMENT(A, B, at);                                                                      \
        store<T>(A + at, load<T>(C));                                                              \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_Ldp(T, T2)                                                                         \
    {                                                                                              \
        std::uint8_t* source;                                                                      \
        VM_DEREF(B, ip->c, sizeof(T), source);                                                     \
        store<T>(A, load<T>(source));                                                              \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_Stp(T, T2)                                                                         \
    {                                                                                              \
        std::uint8_t* target;                                                                      \
        VM_DEREF(A, ip->c, sizeof(T), target);                                                     \
        store<T>(target, load<T>(B));                                                              \
        VM_NEXT();                                                                                 \
    }
#define VM_BINARY(T, expression)                                                                   \
    {                                                                                              \
        const T x = load<T>(B);                                                                    \
        const T y = load<T>(C);                                                                    \
        store<T>(A, static_cast<T>(expression));                                                   \
        VM_NEXT();                                                                                 \
    }
#define VM_UNARY(T, R, expression)                                                                 \
    {                                                                                              \
        const T x = load<T>(B);                                                                    \
        store<R>(A, expression);                                                                   \
        VM_NEXT();                                                                                 \
    }
#define VM_COMPARE(T, expression)                                                                  \
    {                                                                                              \
        const T x = load<T>(B);                                                                    \
        const T y = load<T>(C);                                                                    \
        store<std::uint8_t>(A, (expression) ? 1 : 0);                                              \
        VM_NEXT();                                                                                 \
    }
#define VM_COMPARE_BRANCH(T, expression) VM_BRANCH_IF((load<T>(A) expression load<T>(B)), ip->c);
#define VM_EXEC_Add(T, T2) VM_BINARY(T, add(x, y))
#define VM_EXEC_Sub(T, T2) VM_BINARY(T, sub(x, y))
#define VM_EXEC_Mul(T, T2) VM_BINARY(T, mul(x, y))
#define VM_EXEC_AddI(T, T2) VM_UNARY(T, T, add(x, static_cast<T>(static_cast<std::int32_t>(ip->c))))
#define VM_EXEC_Neg(T, T2) VM_UNARY(T, T, neg(x))
#define VM_EXEC_Not(T, T2) VM_UNARY(T, T, static_cast<T>(~x))
#define VM_EXEC_And(T, T2) VM_BINARY(T, x& y)
#define VM_EXEC_Or(T, T2) VM_BINARY(T, x | y)
#define VM_EXEC_Xor(T, T2) VM_BINARY(T, x ^ y)
#define VM_EXEC_Shl(T, T2) VM_UNARY(T, T, shift_left(x, load<std::uint32_t>(C)))
#define VM_EXEC_Shr(T, T2) VM_UNARY(T, T, shift_right(x, load<std::uint32_t>(C)))
#define VM_EXEC_Rol(T, T2) VM_UNARY(T, T, rotate_left(x, load<std::uint32_t>(C)))
#define VM_EXEC_Ror(T, T2) VM_UNARY(T, T, rotate_right(x, load<std::uint32_t>(C)))
#define VM_EXEC_Eq(T, T2) VM_COMPARE(T, x == y)
#define VM_EXEC_Ne(T, T2) VM_COMPARE(T, x != y)
#define VM_EXEC_Lt(T, T2) VM_COMPARE(T, x < y)
#define VM_EXEC_Le(T, T2) VM_COMPARE(T, x <= y)
#define VM_EXEC_JEq(T, T2) VM_COMPARE_BRANCH(T, ==)
#define VM_EXEC_JNe(T, T2) VM_COMPARE_BRANCH(T, !=)
#define VM_EXEC_JTst(T, T2) VM_BRANCH_IF((load<T>(A) & load<T>(B)) != 0, ip->c);
#define VM_EXEC_JNTst(T, T2) VM_BRANCH_IF((load<T>(A) & load<T>(B)) == 0, ip->c);
#define VM_EXEC_JLt(T, T2) VM_COMPARE_BRANCH(T, <)
#define VM_EXEC_JLe(T, T2) VM_COMPARE_BRANCH(T, <=)
#define VM_EXEC_Abs(T, T2) VM_UNARY(T, T, abs(x))
#define VM_EXEC_For(T, T2)                                                                         \
    {                                                                                              \
        const auto step = static_cast<std::int16_t>(ip->aux);                                      \
        const T last = load<T>(A);                                                                 \
        const T next = add(last, static_cast<T>(step));                                            \
        store<T>(A, next);                                                                         \
        /* A step past the end of T (it wrapped) ends the loop, as a step past the limit. */       \
        VM_BRANCH_IF(step > 0 ? next > last && next <= load<T>(B)                                  \
                              : next < last && next >= load<T>(B),                                 \
                     ip->c);                                                                       \
    }
#define VM_EXEC_Sqrt(T, T2) VM_UNARY(T, T, std::sqrt(x))
#define VM_EXEC_Trunc(T, R) VM_UNARY(T, R, (truncate<R>(x)))
#define VM_EXEC_Cvt(T, R) VM_UNARY(T, R, (convert<R>(x)))
#define VM_EXEC_Range(T, T2)                                                                       \
    {                                                                                              \
        const T x = load<T>(A);                                                                    \
        if (x < load<T>(B) || x > load<T>(B + sizeof(T))) {                                        \
            VM_TRAP(Trap::SubrangeViolation);                                                      \
        }                                                                                          \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_IdxDim(T1, T2)                                                                     \
    {                                                                                              \
        const auto element = std::int64_t{load<std::int32_t>(C)} - load<std::int32_t>(B);          \
        if (static_cast<std::uint64_t>(element) >= load<std::uint32_t>(B + 4)) {                   \
            VM_TRAP(Trap::IndexOutOfRange);                                                        \
        }                                                                                          \
        store<std::int32_t>(A, static_cast<std::int32_t>(element));                                \
        VM_NEXT();                                                                                 \
    }
#define VM_CHECKED_DIVISION(T, operation)                                                          \
    {                                                                                              \
        const T x = load<T>(B);                                                                    \
        const T y = load<T>(C);                                                                    \
        if constexpr (std::is_integral_v<T>) {                                                     \
            if (y == 0) {                                                                          \
                VM_TRAP(Trap::DivisionByZero);                                                     \
            }                                                                                      \
        }                                                                                          \
        store<T>(A, operation(x, y));                                                              \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_CMov(T, T2)                                                                        \
    if (load<std::uint8_t>(B) != 0) {                                                              \
        store<T>(A, load<T>(C));                                                                   \
    }                                                                                              \
    VM_NEXT();
#define VM_EXEC_Div(T, T2) VM_CHECKED_DIVISION(T, divide)
#define VM_EXEC_Mod(T, T2) VM_CHECKED_DIVISION(T, modulo)
