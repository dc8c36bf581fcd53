#pragma once

#include "compiled_code.hpp"
#include "jit_context.hpp"
#include "step_context.hpp"

#include <cstdint>
#include <deque>
#include <optional>
#include <type_traits>
#include <vector>
#include <xbyak/xbyak.h>

// Bytecode to x86-64, one instruction at a time, in the order of the code: every VM instruction
// gets a label, so jumps, calls, returns and a resumed task land exactly where the interpreter
// would. Operands stay in VM memory, addressed from the base registers the way the interpreter
// addresses them from its base table; the hot families are emitted as machine instructions and
// every other instruction calls its step function (the interpreter's own semantics).
//
// Registers while compiled code runs (all callee-saved, so step functions keep them):
//   rbx  instructions left in the slice     r12  VM memory (Static)
//   r13  the frame (Out is frame + the POU's frame size)     r14  self
//   r15  the JitContext                      rbp  VM calls made by `call` in this run
//
// A VM call is also a machine `call`, so that its return is a `ret` the processor predicts; the
// activation goes on the task's call stack as well, which is what a return to a caller entered
// before this run (a resumed task) follows, through the address of the caller's instruction.
//
// Instruction counting is the interpreter's, per basic block (block_formation.hpp): a block
// subtracts its length when it ends (at its jump, call or return, or where it falls into the
// next block), a trap its length so far. Counts therefore agree with the interpreter's at every
// taken jump, call, return and trap, which are the only places where they are observed.
//
// The files: translator.cpp walks the blocks and dispatches each instruction to the emitter of
// its family's group (the list below); translator_operands.cpp says where operands are and
// which register still holds one; translator_control.cpp holds exits, conditions, branches and
// the step-function call; emit_<group>.cpp emits one group of families each.

namespace eposp::vm::jit {

/// Every family of the opcode list (opcodes.hpp) with the group, and file emit_<group>.cpp, that
/// emits it. The rare or involved families are Step: their step function is fast enough.
#define EPOSP_JIT_FAMILIES(X)                                                                      \
    X(Nop, Jumps)                                                                                  \
    X(Jmp, Jumps)                                                                                  \
    X(Jt, Jumps)                                                                                   \
    X(Jf, Jumps)                                                                                   \
    X(JtX, Jumps)                                                                                  \
    X(JfX, Jumps)                                                                                  \
    X(JTab, Jumps)                                                                                 \
    X(Call, Calls)                                                                                 \
    X(CallFb, Calls)                                                                               \
    X(CallFbP, Calls)                                                                              \
    X(CallNative, Calls)                                                                           \
    X(Ret, Calls)                                                                                  \
    X(Mov, Moves)                                                                                  \
    X(Ldi, Moves)                                                                                  \
    X(Ldx, Moves)                                                                                  \
    X(Stx, Moves)                                                                                  \
    X(Ldp, Moves)                                                                                  \
    X(Stp, Moves)                                                                                  \
    X(CMov, Moves)                                                                                 \
    X(Add, Arithmetic)                                                                             \
    X(Sub, Arithmetic)                                                                             \
    X(Mul, Arithmetic)                                                                             \
    X(Div, Arithmetic)                                                                             \
    X(Mod, Arithmetic)                                                                             \
    X(AddI, Arithmetic)                                                                            \
    X(Neg, Arithmetic)                                                                             \
    X(Sqrt, Arithmetic)                                                                            \
    X(NotB, Logic)                                                                                 \
    X(Not, Logic)                                                                                  \
    X(And, Logic)                                                                                  \
    X(Or, Logic)                                                                                   \
    X(Xor, Logic)                                                                                  \
    X(Shl, Logic)                                                                                  \
    X(Shr, Logic)                                                                                  \
    X(Eq, Comparisons)                                                                             \
    X(Ne, Comparisons)                                                                             \
    X(Lt, Comparisons)                                                                             \
    X(Le, Comparisons)                                                                             \
    X(JEq, Comparisons)                                                                            \
    X(JNe, Comparisons)                                                                            \
    X(JLt, Comparisons)                                                                            \
    X(JLe, Comparisons)                                                                            \
    X(JTst, Comparisons)                                                                           \
    X(JNTst, Comparisons)                                                                          \
    X(For, Comparisons)                                                                            \
    X(Cvt, Conversions)                                                                            \
    X(MovN, Step)                                                                                  \
    X(Addr, Step)                                                                                  \
    X(IdxA, Step)                                                                                  \
    X(IdxAP, Step)                                                                                 \
    X(LdpN, Step)                                                                                  \
    X(StpN, Step)                                                                                  \
    X(Rol, Step)                                                                                   \
    X(Ror, Step)                                                                                   \
    X(Abs, Step)                                                                                   \
    X(Trunc, Step)                                                                                 \
    X(Range, Step)                                                                                 \
    X(IdxDim, Step)

/// Who emits an instruction: one of the emit_<group>.cpp files, or its step function.
enum class EmitterGroup { Jumps, Calls, Moves, Arithmetic, Logic, Comparisons, Conversions, Step };

/// One tag type per family of the opcode list, so that a family can be named in a template.
namespace families {
#define EPOSP_JIT_FAMILY_TAG(name, fam, ...) struct fam;
EPOSP_VM_OPCODES(EPOSP_JIT_FAMILY_TAG)
#undef EPOSP_JIT_FAMILY_TAG
} // namespace families

/// The group of a family; every family is in EPOSP_JIT_FAMILIES (emit_in_group.hpp needs its
/// emitter declared), so this default is never taken.
template <typename Family>
inline constexpr EmitterGroup kEmitterGroup = EmitterGroup::Step;
#define EPOSP_JIT_FAMILY_GROUP(fam, group)                                                         \
    template <>                                                                                    \
    inline constexpr EmitterGroup kEmitterGroup<families::fam> = EmitterGroup::group;
EPOSP_JIT_FAMILIES(EPOSP_JIT_FAMILY_GROUP)
#undef EPOSP_JIT_FAMILY_GROUP

/// The group of the family of `op`.
constexpr EmitterGroup emitter_group(Opcode op) {
    switch (op) {
#define EPOSP_JIT_OPCODE_GROUP(name, fam, ...)                                                     \
    case Opcode::name:                                                                             \
        return kEmitterGroup<families::fam>;
        EPOSP_VM_OPCODES(EPOSP_JIT_OPCODE_GROUP)
#undef EPOSP_JIT_OPCODE_GROUP
    }
    return EmitterGroup::Step;
}

template <typename T>
inline constexpr bool kInteger = std::is_integral_v<T>;
template <typename T>
inline constexpr bool kFloat = std::is_floating_point_v<T>;

class Translator : public Xbyak::CodeGenerator {
public:
    Translator(const Image& image, CompiledCode& out)
        : Xbyak::CodeGenerator(64 * 1024, Xbyak::AutoGrow), image_(image), out_(out),
          labels_(image.code.size()) {
        setDefaultJmpNEAR(true);
    }

    /// Translates the whole image into `out`.
    void translate();

private:
    enum class Cond { E, NE, L, LE, G, GE, B, BE, A, AE };

    /// An exit from compiled code, emitted after all instructions.
    struct Exit {
        Xbyak::Label label;
        ExitKind kind = ExitKind::Finished;
        std::uint32_t pc = 0;
        std::uint32_t pou = 0;
        std::int64_t charge = 0;
        Trap trap = Trap::DivisionByZero;
        bool trap_from_step = false; ///< the trap is the step function's result in eax
        bool pc_in_ecx = false;      ///< a jump-table target known only at run time
    };

    void emit_entry_and_exit();
    void emit_instruction(const Instruction& ins);
    void emit_exits();

    // Where things are (translator_operands.cpp).
    Xbyak::Address at(std::uint32_t field, int bytes, std::int64_t extra = 0);
    Xbyak::RegExp address_of(std::uint32_t field, std::int64_t extra = 0);
    const Xbyak::AddressFrame& sized(int bytes) const;
    static Xbyak::Reg work(const Xbyak::Reg64& r, int bytes);
    static Xbyak::Reg part(const Xbyak::Reg64& r, int bytes);
    /// A register holding the value of an operand.
    struct Held {
        std::uint32_t field = 0;
        int bytes = 0;
    };
    static bool holds(const std::optional<Held>& held, std::uint32_t field, int bytes);
    void load(const Xbyak::Reg64& r, std::uint32_t field, int bytes, bool sign);
    void load64(std::uint32_t field, int bytes, bool sign);
    void store(std::uint32_t field, int bytes, const Xbyak::Reg64& r);
    template <typename T>
    void float_load(std::uint32_t field);
    template <typename T>
    void float_store(std::uint32_t field);
    /// Checks the index of an indexed access (trapping out of range) and leaves the element's
    /// address expression; uses rax.
    Xbyak::RegExp element(const Instruction& ins, std::uint32_t array_field,
                          std::uint32_t index_field);

    // Control (translator_control.cpp).
    std::int64_t charge_so_far() const { return std::int64_t{index_} - segment_ + 1; }
    void charge_block() { sub(rbx, static_cast<std::uint32_t>(charge_so_far())); }
    Xbyak::Label& exit(Exit exit);
    /// A trap at the instruction being translated, charging its block so far.
    Exit trap_here() const;
    Xbyak::Label& trap_exit(Trap trap);
    Xbyak::Label& suspend_exit(std::uint32_t pc, std::uint32_t pou);
    void jump_if(Cond cond, const Xbyak::Label& label);
    void set_if(Cond cond, const Xbyak::Reg8& r);
    static Cond negate(Cond cond);
    /// The taken side of a branch whose block is charged: a safe point, then the target.
    void jump_to(std::uint32_t target);
    /// A conditional branch: `emit_skip` jumps to its label where the branch is not taken.
    template <typename EmitSkip>
    void branch(std::uint32_t target, EmitSkip&& emit_skip) {
        Xbyak::Label skip;
        emit_skip(skip);
        jump_to(target);
        L(skip);
    }
    void branch_if(Cond cond, std::uint32_t target) {
        branch(target, [&](Xbyak::Label& skip) { jump_if(negate(cond), skip); });
    }
    void call_step(const Instruction& ins);

    // The shapes of most data instructions: [A] := [B] op [C], and [A] := op [B].
    template <typename T, typename Operation>
    bool binary(const Instruction& ins, Operation&& operation) {
        constexpr int bytes = sizeof(T);
        load(rax, ins.b, bytes, false);
        if constexpr (bytes >= 4) {
            operation(work(rax, bytes), at(ins.c, bytes));
        } else {
            load(rcx, ins.c, bytes, false);
            operation(work(rax, bytes), work(rcx, bytes));
        }
        store(ins.a, bytes, rax);
        return true;
    }
    template <typename T, typename Operation>
    bool unary(const Instruction& ins, Operation&& operation) {
        load(rax, ins.b, sizeof(T), false);
        operation(work(rax, sizeof(T)));
        store(ins.a, sizeof(T), rax);
        return true;
    }

    // One member per group (emit_<group>.cpp): emits `ins`, or returns false to have its step
    // function called (for a case its family leaves to it).
    template <EmitterGroup Group>
    bool emit_in_group(const Instruction& ins);
    bool emit_jumps(const Instruction& ins);
    bool emit_calls(const Instruction& ins);
    bool emit_moves(const Instruction& ins);
    bool emit_arithmetic(const Instruction& ins);
    bool emit_logic(const Instruction& ins);
    bool emit_comparisons(const Instruction& ins);
    bool emit_conversions(const Instruction& ins);

    // The helpers of single groups, defined in their files.
    void enter(std::uint32_t callee_index);
    void checked_pointer(std::uint32_t pointer_field, std::uint32_t offset, std::uint32_t bytes);
    template <typename T, typename Operation>
    bool float_binary(const Instruction& ins, Operation&& operation);
    template <typename T>
    bool division(const Instruction& ins, bool remainder);
    template <typename T>
    bool shift(const Instruction& ins, bool left);
    template <typename T>
    Cond compare(std::uint32_t x, std::uint32_t y, Cond signed_cond, Cond unsigned_cond);
    template <typename T>
    bool set_compare(const Instruction& ins, Cond signed_cond, Cond unsigned_cond);
    template <typename T>
    bool branch_compare(const Instruction& ins, Cond signed_cond, Cond unsigned_cond);
    template <typename T>
    bool set_float_equality(const Instruction& ins, bool equal);
    template <typename T>
    bool branch_float_equality(const Instruction& ins, bool equal);
    /// ([A] AND [B]) <> 0 (`when_set`) or = 0, then on to the target.
    template <typename T>
    bool bit_test_branch(const Instruction& ins, bool when_set);
    /// = and <> (IEEE for reals: unordered is unequal), as a BOOL or as a branch.
    template <typename T>
    bool equality(const Instruction& ins, bool equal, bool branches);

    // One emitter per family (opcodes.hpp); false means "call the step function". Those of the
    // Step group are never defined: emit_in_group.hpp only names them.
#define EPOSP_JIT_DECLARE_EMITTER(fam, group)                                                      \
    template <typename T, typename R>                                                              \
    bool emit_##fam(const Instruction& ins);
    EPOSP_JIT_FAMILIES(EPOSP_JIT_DECLARE_EMITTER)
#undef EPOSP_JIT_DECLARE_EMITTER

    const Image& image_;
    CompiledCode& out_;
    std::vector<Xbyak::Label> labels_; ///< one per instruction
    std::deque<Exit> exits_;           ///< a deque: labels must not move
    Xbyak::Label exit_common_;
    std::uint32_t pou_index_ = 0;
    const Pou* pou_ = nullptr;
    std::uint32_t index_ = 0;                      ///< the instruction being translated
    std::uint32_t segment_ = 0;                    ///< the first instruction of its basic block
    std::optional<Held> held_rax_, held_xmm0_;     ///< at the start of this instruction
    std::optional<Held> stored_rax_, stored_xmm0_; ///< left by this instruction
};

} // namespace eposp::vm::jit
