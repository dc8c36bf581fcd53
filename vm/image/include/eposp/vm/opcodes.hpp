#pragma once

#include "eposp/vm/scalar.hpp"

#include <cstdint>
#include <string_view>

// The instruction set. Every instruction is 16 bytes: opcode (16 bits), aux (16 bits) and three
// 32-bit fields A, B, C (instruction.hpp). A data operand names a base and an offset; the
// verifier proves every static operand inside its area, so the interpreter never checks them.
//
// Why this shape: IEC 61131-3 has no recursion, FB instances are static and every type is known
// when compiling, so a 3-address memory-to-memory form with typed opcodes needs no register
// allocation in codegen, no type tags and no operand stack; an operand costs one table load
// (its base) and an add. Fixed width keeps jump targets plain instruction indices (no jump into
// the middle of an instruction can even be expressed) and decoding branch-free.
//
// Notation below: [X] is the memory operand X, typed by the opcode's suffix; #X is the raw
// 32-bit field X; desc is array descriptor number aux (lower bound, count, element size, and
// whether [index] is an INT or a DINT).
// Families are written once and instantiated per width or type; the suffix says which:
//   8/16/32/64  the bit width, sign-agnostic (two's complement wrap-around)
//   I8..I64, U8..U64, F32, F64, Bool  a typed value
//
//  opcode            A        B        C        semantics
//  Nop               -        -        -        nothing
//  Jmp               target   -        -        goto target                           (safe point)
//  Jt / Jf           [BOOL]   target   -        if [A] (not [A]) goto B               (safe point)
//  JtX / JfX         [array]  [index]  target   if array[[B]] (not) goto C, BOOL elements,
//                                               checked by desc                 (safe point)
//  Call              pou      -        -        call function: frame := out area      (safe point)
//  CallFb            inst     pou      -        call FB/program body, self := &[A]    (safe point)
//  CallFbP           [ptr]    pou      -        call FB body, self := [A] (checked)   (safe point)
//  CallNative        import   [args]   -        host function on the argument block   (safe point)
//  Ret               -        -        -        return to the caller (end of the task's run)
//  MovN              [dst]    [src]    #size    copy #C bytes (STRUCT, STRING, ARRAY)
//  Addr              [ptr]    [x]      #size    [A] := address of [B] (REF, ADR)
//  IdxA              [ptr]    [array]  [index]   [A] := &array[[C]]           checked by desc
//  IdxAP             [ptr]    [ptr]    [index]   [A] := [B] + ([C]-lo)*size   checked by desc
//  LdpN / StpN       [dst]/[ptr] [ptr]/[src] #size  block copy through a pointer (checked)
//  NotB              [BOOL]   [BOOL]   -        logical NOT
//  Mov<w>            [dst]    [src]    -        [A] := [B]
//  Ldi<w>            [dst]    #lo      #hi      [A] := #B | #C << 32, truncated to w
//  Ldx<w>            [dst]    [array]  [index]   [A] := array[[C]]            checked by desc
//  Stx<w>            [array]  [index]  [src]    array[[B]] := [C]            checked by desc
//  Ldp<w>            [dst]    [ptr]    #off     [A] := *([B] + #C)           NULL/range checked
//  Stp<w>            [ptr]    [src]    #off     *([A] + #C) := [B]           NULL/range checked
//  Add/Sub/Mul<w>    [dst]    [x]      [y]      wrap-around arithmetic
//  AddI<w>           [dst]    [x]      #imm     [A] := [B] + sign-extended #C
//  Neg/Not<w>        [dst]    [x]      -        two's complement / bitwise complement
//  And/Or/Xor<w>     [dst]    [x]      [y]      bitwise (BOOL uses the 8-bit forms)
//  Shl/Shr<w>        [dst]    [x]      [UDINT]  logical shift; a count >= w gives 0
//  Rol/Ror<w>        [dst]    [x]      [UDINT]  rotate by count mod w
//  Eq/Ne<w>          [BOOL]   [x]      [y]      bit equality
//  JEq/JNe<w>        [x]      [y]      target   compare and branch                (safe point)
//  JTst/JNTst<w>     [x]      [mask]   target   if ([A] AND [B]) <> 0 (= 0) goto C    (safe point)
//  JTab<T>           [x]      table    target   goto entry [A] - low (modulo 2^32) of jump
//                                               table B, or C past its end: a CASE  (safe point)
//  Div/Mod<T>        [dst]    [x]      [y]      truncating; integer /0 traps, MIN/-1 wraps
//  Lt/Le<T>          [BOOL]   [x]      [y]      ordered compare (GT/GE: swap x and y)
//  JLt/JLe<T>        [x]      [y]      target   compare and branch                (safe point)
//  Abs<T>            [dst]    [x]      -        absolute value (MIN stays MIN)
//  For<I>            [var]    [limit]  target   FOR loop back-edge, step in aux: [A] += step;
//                                               if it did not wrap around I and step > 0 ?
//                                               [A] <= [B] : [A] >= [B] goto C (safe point)
//  Add/Sub/Mul/Neg/Eq/Ne/JEq/JNe/Sqrt<F>        IEEE 754 (F32, F64)
//  Cvt<T><U>         [dst U]  [src T]  -        IEC conversion: ints wrap, to BOOL is <> 0,
//                                               REAL to int rounds to nearest, ties to
//                                               even, and saturates (NaN gives 0)
//  Trunc<F>          [LINT]   [F]      -        TRUNC: toward zero, saturating
//  Range<I>          [x]      [lo, hi] -        trap unless lo <= [A] <= hi: a store into a
//                                               subrange type (B: two values of the type)
//  IdxDim            [DINT]   [lo, n]  [DINT]   [A] := [C] - lo, trap unless < n: one index of
//                                               an ARRAY[*] (B: DINT lower bound, UDINT count)
//  CMov<w>           [dst]    [BOOL]   [src]    if [B] then [A] := [C]: an IF choosing between
//                                               two cheap values, without a branch

namespace eposp::vm {

/// What an instruction field means, for the verifier and the disassembler.
enum class Field : std::uint8_t {
    None,
    Read,            ///< a memory operand read with the given size
    Write,           ///< a memory operand written with the given size
    ReadN,           ///< read, size in field C
    WriteN,          ///< written, size in field C
    Imm,             ///< a raw 32-bit value
    Size,            ///< a byte count (for the ...N forms)
    Target,          ///< an instruction index inside the same POU
    Pou,             ///< a POU index
    Import,          ///< a native import index
    Instance,        ///< an FB instance operand, sized by the POU in field B
    ArrayRead,       ///< an array operand, sized by the descriptor in aux; size is the access width
    ArrayWrite,      ///< the same, written
    ArrayIndex,      ///< the index of an indexed access, read with the descriptor's index size
    NativeArguments, ///< the argument block of the native import in field A
    JumpTable,       ///< a jump table index
};

/// What the aux field of an instruction holds.
enum class Aux : std::uint8_t {
    None,  ///< must be 0
    Array, ///< an array descriptor index
    Step,  ///< a signed 16-bit loop step
};

struct FieldSpec {
    Field field = Field::None;
    std::uint8_t size = 0; ///< bytes, for Read and Write
};

// Operand spellings used in the list below. Array operands carry the width of the element
// access (AR0: only its address is taken).
#define EPOSP_VM_FIELD(kind, size)                                                                 \
    ::eposp::vm::FieldSpec {                                                                       \
        ::eposp::vm::Field::kind, size                                                             \
    }
#define EPOSP_VM_F__ EPOSP_VM_FIELD(None, 0)
#define EPOSP_VM_F_R1 EPOSP_VM_FIELD(Read, 1)
#define EPOSP_VM_F_R2 EPOSP_VM_FIELD(Read, 2)
#define EPOSP_VM_F_R4 EPOSP_VM_FIELD(Read, 4)
#define EPOSP_VM_F_R8 EPOSP_VM_FIELD(Read, 8)
#define EPOSP_VM_F_W1 EPOSP_VM_FIELD(Write, 1)
#define EPOSP_VM_F_W2 EPOSP_VM_FIELD(Write, 2)
#define EPOSP_VM_F_W4 EPOSP_VM_FIELD(Write, 4)
#define EPOSP_VM_F_W8 EPOSP_VM_FIELD(Write, 8)
// A pair of values of width 1..8 (RP1..RP8): a subrange's bounds.
#define EPOSP_VM_F_RP1 EPOSP_VM_FIELD(Read, 2)
#define EPOSP_VM_F_RP2 EPOSP_VM_FIELD(Read, 4)
#define EPOSP_VM_F_RP4 EPOSP_VM_FIELD(Read, 8)
#define EPOSP_VM_F_RP8 EPOSP_VM_FIELD(Read, 16)
#define EPOSP_VM_F_RN EPOSP_VM_FIELD(ReadN, 0)
#define EPOSP_VM_F_WN EPOSP_VM_FIELD(WriteN, 0)
#define EPOSP_VM_F_IM EPOSP_VM_FIELD(Imm, 0)
#define EPOSP_VM_F_SZ EPOSP_VM_FIELD(Size, 0)
#define EPOSP_VM_F_JT EPOSP_VM_FIELD(Target, 0)
#define EPOSP_VM_F_PO EPOSP_VM_FIELD(Pou, 0)
#define EPOSP_VM_F_IX EPOSP_VM_FIELD(Import, 0)
#define EPOSP_VM_F_IN EPOSP_VM_FIELD(Instance, 0)
#define EPOSP_VM_F_AR0 EPOSP_VM_FIELD(ArrayRead, 0)
#define EPOSP_VM_F_AR1 EPOSP_VM_FIELD(ArrayRead, 1)
#define EPOSP_VM_F_AR2 EPOSP_VM_FIELD(ArrayRead, 2)
#define EPOSP_VM_F_AR4 EPOSP_VM_FIELD(ArrayRead, 4)
#define EPOSP_VM_F_AR8 EPOSP_VM_FIELD(ArrayRead, 8)
#define EPOSP_VM_F_AW1 EPOSP_VM_FIELD(ArrayWrite, 1)
#define EPOSP_VM_F_AW2 EPOSP_VM_FIELD(ArrayWrite, 2)
#define EPOSP_VM_F_AW4 EPOSP_VM_FIELD(ArrayWrite, 4)
#define EPOSP_VM_F_AW8 EPOSP_VM_FIELD(ArrayWrite, 8)
#define EPOSP_VM_F_AI EPOSP_VM_FIELD(ArrayIndex, 0)
#define EPOSP_VM_F_NA EPOSP_VM_FIELD(NativeArguments, 0)
#define EPOSP_VM_F_TB EPOSP_VM_FIELD(JumpTable, 0)

// The lists: OP(name, family, T1, T2, aux, A, B, C). `family` names the semantics
// (the interpreter defines one handler per family), T1/T2 are the C++ types it works on.
#define EPOSP_VM_FOR_WIDTHS(M, OP)                                                                 \
    M(OP, 8, 1, std::uint8_t)                                                                      \
    M(OP, 16, 2, std::uint16_t) M(OP, 32, 4, std::uint32_t) M(OP, 64, 8, std::uint64_t)
#define EPOSP_VM_FOR_INTS(M, OP)                                                                   \
    M(OP, I8, 1, std::int8_t)                                                                      \
    M(OP, I16, 2, std::int16_t)                                                                    \
    M(OP, I32, 4, std::int32_t)                                                                    \
    M(OP, I64, 8, std::int64_t)                                                                    \
    M(OP, U8, 1, std::uint8_t)                                                                     \
    M(OP, U16, 2, std::uint16_t) M(OP, U32, 4, std::uint32_t) M(OP, U64, 8, std::uint64_t)
#define EPOSP_VM_FOR_FLOATS(M, OP) M(OP, F32, 4, float) M(OP, F64, 8, double)
#define EPOSP_VM_FOR_SCALARS(M, OP)                                                                \
    M(OP, Bool, 1, ::eposp::vm::BoolByte) EPOSP_VM_FOR_INTS(M, OP) EPOSP_VM_FOR_FLOATS(M, OP)
// A second copy of the scalar list for the inner loop of the conversion matrix (a macro cannot
// expand itself).
#define EPOSP_VM_FOR_SCALARS_INNER(M, ...)                                                         \
    M(Bool, 1, ::eposp::vm::BoolByte, __VA_ARGS__)                                                 \
    M(I8, 1, std::int8_t, __VA_ARGS__)                                                             \
    M(I16, 2, std::int16_t, __VA_ARGS__)                                                           \
    M(I32, 4, std::int32_t, __VA_ARGS__)                                                           \
    M(I64, 8, std::int64_t, __VA_ARGS__)                                                           \
    M(U8, 1, std::uint8_t, __VA_ARGS__)                                                            \
    M(U16, 2, std::uint16_t, __VA_ARGS__)                                                          \
    M(U32, 4, std::uint32_t, __VA_ARGS__)                                                          \
    M(U64, 8, std::uint64_t, __VA_ARGS__) M(F32, 4, float, __VA_ARGS__)                            \
        M(F64, 8, double, __VA_ARGS__)

#define EPOSP_VM_F(X) EPOSP_VM_F_##X
#define EPOSP_VM_OP(OP, name, family, T1, T2, aux, a, b, c)                                        \
    OP(name, family, T1, T2, ::eposp::vm::Aux::aux, EPOSP_VM_F(a), EPOSP_VM_F(b), EPOSP_VM_F(c))

#define EPOSP_VM_WIDTH_OPS(OP, B, N, T)                                                            \
    EPOSP_VM_OP(OP, Mov##B, Mov, T, T, None, W##N, R##N, _)                                        \
    EPOSP_VM_OP(OP, Ldi##B, Ldi, T, T, None, W##N, IM, IM)                                         \
    EPOSP_VM_OP(OP, Ldx##B, Ldx, T, T, Array, W##N, AR##N, AI)                                     \
    EPOSP_VM_OP(OP, Stx##B, Stx, T, T, Array, AW##N, AI, R##N)                                     \
    EPOSP_VM_OP(OP, Ldp##B, Ldp, T, T, None, W##N, R8, IM)                                         \
    EPOSP_VM_OP(OP, Stp##B, Stp, T, T, None, R8, R##N, IM)                                         \
    EPOSP_VM_OP(OP, Add##B, Add, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, Sub##B, Sub, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, Mul##B, Mul, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, AddI##B, AddI, T, T, None, W##N, R##N, IM)                                     \
    EPOSP_VM_OP(OP, Neg##B, Neg, T, T, None, W##N, R##N, _)                                        \
    EPOSP_VM_OP(OP, Not##B, Not, T, T, None, W##N, R##N, _)                                        \
    EPOSP_VM_OP(OP, And##B, And, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, Or##B, Or, T, T, None, W##N, R##N, R##N)                                       \
    EPOSP_VM_OP(OP, Xor##B, Xor, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, Shl##B, Shl, T, T, None, W##N, R##N, R4)                                       \
    EPOSP_VM_OP(OP, Shr##B, Shr, T, T, None, W##N, R##N, R4)                                       \
    EPOSP_VM_OP(OP, Rol##B, Rol, T, T, None, W##N, R##N, R4)                                       \
    EPOSP_VM_OP(OP, Ror##B, Ror, T, T, None, W##N, R##N, R4)                                       \
    EPOSP_VM_OP(OP, Eq##B, Eq, T, T, None, W1, R##N, R##N)                                         \
    EPOSP_VM_OP(OP, Ne##B, Ne, T, T, None, W1, R##N, R##N)                                         \
    EPOSP_VM_OP(OP, JEq##B, JEq, T, T, None, R##N, R##N, JT)                                       \
    EPOSP_VM_OP(OP, JNe##B, JNe, T, T, None, R##N, R##N, JT)

#define EPOSP_VM_BIT_TEST_OPS(OP, B, N, T)                                                         \
    EPOSP_VM_OP(OP, JTst##B, JTst, T, T, None, R##N, R##N, JT)                                     \
    EPOSP_VM_OP(OP, JNTst##B, JNTst, T, T, None, R##N, R##N, JT)

#define EPOSP_VM_ORDERED_OPS(OP, S, N, T)                                                          \
    EPOSP_VM_OP(OP, Div##S, Div, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, Lt##S, Lt, T, T, None, W1, R##N, R##N)                                         \
    EPOSP_VM_OP(OP, Le##S, Le, T, T, None, W1, R##N, R##N)                                         \
    EPOSP_VM_OP(OP, JLt##S, JLt, T, T, None, R##N, R##N, JT)                                       \
    EPOSP_VM_OP(OP, JLe##S, JLe, T, T, None, R##N, R##N, JT)                                       \
    EPOSP_VM_OP(OP, Abs##S, Abs, T, T, None, W##N, R##N, _)

#define EPOSP_VM_INT_OPS(OP, S, N, T)                                                              \
    EPOSP_VM_OP(OP, Mod##S, Mod, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, For##S, For, T, T, Step, W##N, R##N, JT)

#define EPOSP_VM_RANGE_OPS(OP, S, N, T) EPOSP_VM_OP(OP, Range##S, Range, T, T, None, R##N, RP##N, _)

#define EPOSP_VM_FLOAT_OPS(OP, S, N, T)                                                            \
    EPOSP_VM_OP(OP, Add##S, Add, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, Sub##S, Sub, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, Mul##S, Mul, T, T, None, W##N, R##N, R##N)                                     \
    EPOSP_VM_OP(OP, Neg##S, Neg, T, T, None, W##N, R##N, _)                                        \
    EPOSP_VM_OP(OP, Sqrt##S, Sqrt, T, T, None, W##N, R##N, _)                                      \
    EPOSP_VM_OP(OP, Eq##S, Eq, T, T, None, W1, R##N, R##N)                                         \
    EPOSP_VM_OP(OP, Ne##S, Ne, T, T, None, W1, R##N, R##N)                                         \
    EPOSP_VM_OP(OP, JEq##S, JEq, T, T, None, R##N, R##N, JT)                                       \
    EPOSP_VM_OP(OP, JNe##S, JNe, T, T, None, R##N, R##N, JT)                                       \
    EPOSP_VM_OP(OP, Trunc##S, Trunc, T, std::int64_t, None, W8, R##N, _)

#define EPOSP_VM_SELECT_OPS(OP, B, N, T) EPOSP_VM_OP(OP, CMov##B, CMov, T, T, None, W##N, R1, R##N)

#define EPOSP_VM_CVT_CELL(D, DN, DT, OP, S, SN, ST)                                                \
    EPOSP_VM_OP(OP, Cvt##S##D, Cvt, ST, DT, None, W##DN, R##SN, _)
#define EPOSP_VM_CVT_ROW(OP, S, SN, ST) EPOSP_VM_FOR_SCALARS_INNER(EPOSP_VM_CVT_CELL, OP, S, SN, ST)

#define EPOSP_VM_OPCODES(OP)                                                                       \
    EPOSP_VM_OP(OP, Nop, Nop, void, void, None, _, _, _)                                           \
    EPOSP_VM_OP(OP, Jmp, Jmp, void, void, None, JT, _, _)                                          \
    EPOSP_VM_OP(OP, Jt, Jt, void, void, None, R1, JT, _)                                           \
    EPOSP_VM_OP(OP, Jf, Jf, void, void, None, R1, JT, _)                                           \
    EPOSP_VM_OP(OP, Call, Call, void, void, None, PO, _, _)                                        \
    EPOSP_VM_OP(OP, CallFb, CallFb, void, void, None, IN, PO, _)                                   \
    EPOSP_VM_OP(OP, CallFbP, CallFbP, void, void, None, R8, PO, _)                                 \
    EPOSP_VM_OP(OP, CallNative, CallNative, void, void, None, IX, NA, _)                           \
    EPOSP_VM_OP(OP, Ret, Ret, void, void, None, _, _, _)                                           \
    EPOSP_VM_OP(OP, MovN, MovN, void, void, None, WN, RN, SZ)                                      \
    EPOSP_VM_OP(OP, Addr, Addr, void, void, None, W8, RN, SZ)                                      \
    EPOSP_VM_OP(OP, IdxA, IdxA, void, void, Array, W8, AR0, AI)                                    \
    EPOSP_VM_OP(OP, IdxAP, IdxAP, void, void, Array, W8, R8, AI)                                   \
    EPOSP_VM_OP(OP, LdpN, LdpN, void, void, None, WN, R8, SZ)                                      \
    EPOSP_VM_OP(OP, StpN, StpN, void, void, None, R8, RN, SZ)                                      \
    EPOSP_VM_OP(OP, NotB, NotB, void, void, None, W1, R1, _)                                       \
    EPOSP_VM_FOR_WIDTHS(EPOSP_VM_WIDTH_OPS, OP)                                                    \
    EPOSP_VM_FOR_INTS(EPOSP_VM_ORDERED_OPS, OP)                                                    \
    EPOSP_VM_FOR_FLOATS(EPOSP_VM_ORDERED_OPS, OP)                                                  \
    EPOSP_VM_FOR_INTS(EPOSP_VM_INT_OPS, OP)                                                        \
    EPOSP_VM_FOR_FLOATS(EPOSP_VM_FLOAT_OPS, OP)                                                    \
    EPOSP_VM_FOR_SCALARS(EPOSP_VM_CVT_ROW, OP)                                                     \
    EPOSP_VM_FOR_WIDTHS(EPOSP_VM_BIT_TEST_OPS, OP)                                                 \
    EPOSP_VM_OP(OP, JtX, JtX, void, void, Array, AR1, AI, JT)                                      \
    EPOSP_VM_OP(OP, JfX, JfX, void, void, Array, AR1, AI, JT)                                      \
    EPOSP_VM_FOR_INTS(EPOSP_VM_RANGE_OPS, OP)                                                      \
    EPOSP_VM_OP(OP, IdxDim, IdxDim, void, void, None, W4, R8, R4)                                  \
    EPOSP_VM_OP(OP, JTabI16, JTab, std::int16_t, void, None, R2, TB, JT)                           \
    EPOSP_VM_OP(OP, JTabU16, JTab, std::uint16_t, void, None, R2, TB, JT)                          \
    EPOSP_VM_OP(OP, JTab32, JTab, std::uint32_t, void, None, R4, TB, JT)                           \
    EPOSP_VM_FOR_WIDTHS(EPOSP_VM_SELECT_OPS, OP)

#define EPOSP_VM_ENUMERATOR(name, ...) name,
enum class Opcode : std::uint16_t { EPOSP_VM_OPCODES(EPOSP_VM_ENUMERATOR) };
#undef EPOSP_VM_ENUMERATOR

#define EPOSP_VM_COUNT(...) +1
inline constexpr std::uint16_t kOpcodeCount = 0 EPOSP_VM_OPCODES(EPOSP_VM_COUNT);
#undef EPOSP_VM_COUNT

/// What the verifier and the disassembler need to know about one opcode.
struct OpcodeInfo {
    std::string_view name;
    Aux aux;
    FieldSpec a, b, c;
};

/// The row for `op`; `op` must be < kOpcodeCount.
const OpcodeInfo& opcode_info(Opcode op);

} // namespace eposp::vm
