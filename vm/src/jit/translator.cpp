#include "compiled_code.hpp"
#include "jit_context.hpp"
#include "step_context.hpp"

#include <cstddef>
#include <deque>
#include <optional>
#include <type_traits>
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
// Instruction counting is the interpreter's, per basic block: a block subtracts its length
// when it ends (at its jump, call or return, or where it falls into the next block), a trap
// its length so far. Counts therefore agree with the interpreter's at every taken jump, call,
// return and trap, which are the only places where they are observed.

namespace eposp::vm::jit {

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

    // Where things are.
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

    // Control.
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
    void branch(std::uint32_t target, EmitSkip&& emit_skip);
    void branch_if(Cond cond, std::uint32_t target) {
        branch(target, [&](Xbyak::Label& skip) { jump_if(negate(cond), skip); });
    }
    /// Checks the index of an indexed access (trapping out of range) and leaves the element's
    /// address expression; uses rax.
    Xbyak::RegExp element(const Instruction& ins, std::uint32_t array_field,
                          std::uint32_t index_field);
    void call_step(const Instruction& ins);
    void enter(std::uint32_t callee_index);

    // Comparisons, leaving flags for the condition returned.
    template <typename T>
    Cond compare(std::uint32_t x, std::uint32_t y, Cond signed_cond, Cond unsigned_cond);
    template <typename T>
    void float_load(std::uint32_t field);
    template <typename T>
    void float_store(std::uint32_t field);

    template <typename T, typename Operation>
    bool binary(const Instruction& ins, Operation&& operation);
    template <typename T, typename Operation>
    bool float_binary(const Instruction& ins, Operation&& operation);
    template <typename T, typename Operation>
    bool unary(const Instruction& ins, Operation&& operation);
    template <typename T>
    bool shift(const Instruction& ins, bool left);
    template <typename T>
    bool division(const Instruction& ins, bool remainder);
    /// Checks the pointer at `pointer_field` as the interpreter does (not NULL, `bytes` at
    /// pointer + `offset` inside memory) and leaves it in rax.
    void checked_pointer(std::uint32_t pointer_field, std::uint32_t offset, std::uint32_t bytes);
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

    // One emitter per family (opcodes.hpp); false means "call the step function".
#define VM_FAMILY(family)                                                                          \
    template <typename T, typename R>                                                              \
    bool emit_##family(const Instruction& ins);
    VM_FAMILY(Nop)
    VM_FAMILY(Jmp)
    VM_FAMILY(Jt)
    VM_FAMILY(Jf)
    VM_FAMILY(JtX)
    VM_FAMILY(JfX)
    VM_FAMILY(JTab)
    VM_FAMILY(Call)
    VM_FAMILY(CallFb)
    VM_FAMILY(CallFbP)
    VM_FAMILY(CallNative)
    VM_FAMILY(Ret)
    VM_FAMILY(NotB)
    VM_FAMILY(Mov)
    VM_FAMILY(Ldi)
    VM_FAMILY(Ldx)
    VM_FAMILY(Stx)
    VM_FAMILY(Add)
    VM_FAMILY(Sub)
    VM_FAMILY(Mul)
    VM_FAMILY(Div)
    VM_FAMILY(Mod)
    VM_FAMILY(Ldp)
    VM_FAMILY(Stp)
    VM_FAMILY(AddI)
    VM_FAMILY(Neg)
    VM_FAMILY(Not)
    VM_FAMILY(And)
    VM_FAMILY(Or)
    VM_FAMILY(Xor)
    VM_FAMILY(Shl)
    VM_FAMILY(Shr)
    VM_FAMILY(Eq)
    VM_FAMILY(Ne)
    VM_FAMILY(Lt)
    VM_FAMILY(Le)
    VM_FAMILY(JEq)
    VM_FAMILY(JNe)
    VM_FAMILY(JLt)
    VM_FAMILY(JLe)
    VM_FAMILY(JTst)
    VM_FAMILY(JNTst)
    VM_FAMILY(For)
    VM_FAMILY(Sqrt)
    VM_FAMILY(Cvt)
    VM_FAMILY(CMov)
#undef VM_FAMILY
// Rare or involved families: their step function is fast enough.
#define VM_STEP_FAMILY(family)                                                                     \
    template <typename T, typename R>                                                              \
    bool emit_##family(const Instruction&) {                                                       \
        return false;                                                                              \
    }
    VM_STEP_FAMILY(MovN)
    VM_STEP_FAMILY(Addr)
    VM_STEP_FAMILY(IdxA)
    VM_STEP_FAMILY(IdxAP)
    VM_STEP_FAMILY(LdpN)
    VM_STEP_FAMILY(StpN)
    VM_STEP_FAMILY(Rol)
    VM_STEP_FAMILY(Ror)
    VM_STEP_FAMILY(Abs)
    VM_STEP_FAMILY(Trunc)
    VM_STEP_FAMILY(Range)
    VM_STEP_FAMILY(IdxDim)
#undef VM_STEP_FAMILY

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

namespace {

template <typename T>
constexpr bool kInteger = std::is_integral_v<T>;
template <typename T>
constexpr bool kFloat = std::is_floating_point_v<T>;

constexpr int context_base(Base base) {
    return static_cast<int>(offsetof(JitContext, step) + offsetof(StepContext, base) +
                            sizeof(std::uint8_t*) * static_cast<int>(base));
}
constexpr int kRemaining = offsetof(JitContext, remaining);
constexpr int kMachineStack = offsetof(JitContext, machine_stack);
constexpr int kCalls = offsetof(JitContext, calls);
constexpr int kDepth = offsetof(JitContext, depth);
constexpr int kStackEnd = offsetof(JitContext, stack_end);
constexpr int kEntries = offsetof(JitContext, entries);
constexpr int kFrameSizes = offsetof(JitContext, frame_sizes);
constexpr int kMemSize = offsetof(JitContext, step) + offsetof(StepContext, mem_size);
constexpr int kExitKind = offsetof(JitContext, exit_kind);
constexpr int kExitPc = offsetof(JitContext, exit_pc);
constexpr int kExitPou = offsetof(JitContext, exit_pou);
constexpr int kExitTrap = offsetof(JitContext, exit_trap);
static_assert(sizeof(Activation) == 16);

// A block ends where control may go elsewhere: a branch, a jump table, a call or return (the
// families without a step function), and a native call, which is a safe point.
bool ends_block(const Instruction& ins) {
    return branch_target(ins) || step_function(ins.opcode) == nullptr ||
           ins.opcode == Opcode::CallNative;
}

/// Where basic blocks start: POU entries, jump targets and what follows a block's end.
std::vector<bool> block_starts(const Image& image) {
    std::vector<bool> starts(image.code.size() + 1, false);
    for (const Pou& pou : image.pous) {
        starts[pou.code_begin] = true;
    }
    for (std::size_t i = 0; i < image.code.size(); ++i) {
        if (auto target = branch_target(image.code[i])) {
            starts[*target] = true;
        }
        if (ends_block(image.code[i])) {
            starts[i + 1] = true;
        }
    }
    for (const JumpTable& table : image.jump_tables) {
        for (std::uint32_t target : table.targets) {
            starts[target] = true;
        }
    }
    return starts;
}

} // namespace

// --- Where things are -------------------------------------------------------------------------

Xbyak::RegExp Translator::address_of(std::uint32_t field, std::int64_t extra) {
    const Operand operand{field};
    std::int64_t displacement = std::int64_t{operand.offset()} + extra;
    switch (operand.base()) {
    case Base::Static:
        return r12 + displacement;
    case Base::Frame:
        return r13 + displacement;
    case Base::Self:
        return r14 + displacement;
    case Base::Out:
        return r13 + (displacement + pou_->frame_size);
    }
    return r12 + displacement;
}

const Xbyak::AddressFrame& Translator::sized(int bytes) const {
    switch (bytes) {
    case 1:
        return byte;
    case 2:
        return word;
    case 4:
        return dword;
    default:
        return qword;
    }
}

Xbyak::Address Translator::at(std::uint32_t field, int bytes, std::int64_t extra) {
    return sized(bytes)[address_of(field, extra)];
}

// Values narrower than 64 bits are worked on in the 32-bit register.
Xbyak::Reg Translator::work(const Xbyak::Reg64& r, int bytes) {
    return bytes == 8 ? Xbyak::Reg(r) : Xbyak::Reg(r.cvt32());
}

Xbyak::Reg Translator::part(const Xbyak::Reg64& r, int bytes) {
    switch (bytes) {
    case 1:
        return r.cvt8();
    case 2:
        return r.cvt16();
    case 4:
        return r.cvt32();
    default:
        return r;
    }
}

// A value an instruction stores from rax (or xmm0) is still there when the next one starts: its
// loads of that operand take the register, which spares the store-to-load forwarding latency on
// every chain of dependent instructions. Valid only from the store to the next instruction's
// first write of the register, and never across a block start. Only the stored bytes are the
// value: above them the register holds whatever the storing instruction computed (a narrowing
// conversion stores 4 bytes of a 64-bit result), so a load that needs more extends them anew.
bool Translator::holds(const std::optional<Held>& held, std::uint32_t field, int bytes) {
    return held && held->field == field && held->bytes == bytes;
}

void Translator::load(const Xbyak::Reg64& r, std::uint32_t field, int bytes, bool sign) {
    const bool hit = bytes >= 4 && holds(held_rax_, field, bytes);
    if (r.getIdx() == rax.getIdx()) {
        held_rax_.reset(); // the caller is about to change rax
        if (hit) {
            return;
        }
    } else if (hit) {
        mov(work(r, bytes), work(rax, bytes));
        return;
    }
    if (bytes < 4) {
        sign ? movsx(r.cvt32(), at(field, bytes)) : movzx(r.cvt32(), at(field, bytes));
    } else {
        mov(work(r, bytes), at(field, bytes));
    }
}

// Into rax, extended to 64 bits.
void Translator::load64(std::uint32_t field, int bytes, bool sign) {
    const bool hit = bytes >= 4 && holds(held_rax_, field, bytes);
    held_rax_.reset();
    if (hit) {
        if (bytes == 4) {
            sign ? movsxd(rax, eax) : mov(eax, eax);
        }
    } else if (bytes == 8) {
        mov(rax, at(field, 8));
    } else if (bytes == 4) {
        sign ? movsxd(rax, at(field, 4)) : mov(eax, at(field, 4));
    } else {
        sign ? movsx(rax, at(field, bytes)) : movzx(eax, at(field, bytes));
    }
}

void Translator::store(std::uint32_t field, int bytes, const Xbyak::Reg64& r) {
    mov(at(field, bytes), part(r, bytes));
    if (r.getIdx() == rax.getIdx() && bytes >= 4) {
        stored_rax_ = Held{field, bytes};
    }
}

template <typename T>
void Translator::float_load(std::uint32_t field) {
    const bool hit = holds(held_xmm0_, field, sizeof(T));
    held_xmm0_.reset();
    if (hit) {
        return;
    }
    if constexpr (sizeof(T) == 4) {
        movss(xmm0, at(field, 4));
    } else {
        movsd(xmm0, at(field, 8));
    }
}

template <typename T>
void Translator::float_store(std::uint32_t field) {
    if constexpr (sizeof(T) == 4) {
        movss(at(field, 4), xmm0);
    } else {
        movsd(at(field, 8), xmm0);
    }
    stored_xmm0_ = Held{field, sizeof(T)};
}

// --- Control ----------------------------------------------------------------------------------

Xbyak::Label& Translator::exit(Exit exit) {
    exits_.push_back(std::move(exit));
    return exits_.back().label;
}

Translator::Exit Translator::trap_here() const {
    Exit e;
    e.kind = ExitKind::Trapped;
    e.pc = index_;
    e.pou = pou_index_;
    e.charge = charge_so_far();
    return e;
}

Xbyak::Label& Translator::trap_exit(Trap trap) {
    Exit e = trap_here();
    e.trap = trap;
    return exit(std::move(e));
}

Xbyak::Label& Translator::suspend_exit(std::uint32_t pc, std::uint32_t pou) {
    Exit e;
    e.kind = ExitKind::Suspended;
    e.pc = pc;
    e.pou = pou;
    return exit(std::move(e));
}

Translator::Cond Translator::negate(Cond cond) {
    switch (cond) {
    case Cond::E:
        return Cond::NE;
    case Cond::NE:
        return Cond::E;
    case Cond::L:
        return Cond::GE;
    case Cond::LE:
        return Cond::G;
    case Cond::G:
        return Cond::LE;
    case Cond::GE:
        return Cond::L;
    case Cond::B:
        return Cond::AE;
    case Cond::BE:
        return Cond::A;
    case Cond::A:
        return Cond::BE;
    case Cond::AE:
        return Cond::B;
    }
    return cond;
}

void Translator::jump_if(Cond cond, const Xbyak::Label& label) {
    switch (cond) {
    case Cond::E:
        return je(label);
    case Cond::NE:
        return jne(label);
    case Cond::L:
        return jl(label);
    case Cond::LE:
        return jle(label);
    case Cond::G:
        return jg(label);
    case Cond::GE:
        return jge(label);
    case Cond::B:
        return jb(label);
    case Cond::BE:
        return jbe(label);
    case Cond::A:
        return ja(label);
    case Cond::AE:
        return jae(label);
    }
}

void Translator::set_if(Cond cond, const Xbyak::Reg8& r) {
    switch (cond) {
    case Cond::E:
        return sete(r);
    case Cond::NE:
        return setne(r);
    case Cond::L:
        return setl(r);
    case Cond::LE:
        return setle(r);
    case Cond::G:
        return setg(r);
    case Cond::GE:
        return setge(r);
    case Cond::B:
        return setb(r);
    case Cond::BE:
        return setbe(r);
    case Cond::A:
        return seta(r);
    case Cond::AE:
        return setae(r);
    }
}

void Translator::jump_to(std::uint32_t target) {
    test(rbx, rbx);
    js(suspend_exit(target, pou_index_));
    jmp(labels_[target]);
}

template <typename EmitSkip>
void Translator::branch(std::uint32_t target, EmitSkip&& emit_skip) {
    Xbyak::Label skip;
    emit_skip(skip);
    jump_to(target);
    L(skip);
}

Xbyak::RegExp Translator::element(const Instruction& ins, std::uint32_t array_field,
                                  std::uint32_t index_field) {
    const ArrayDescriptor& descriptor = image_.arrays[ins.aux];
    held_rax_.reset();
    if (descriptor.index_size == 2) {
        movsx(eax, at(index_field, 2));
    } else {
        mov(eax, at(index_field, 4));
    }
    if (descriptor.lower != 0) {
        sub(eax, static_cast<std::uint32_t>(descriptor.lower));
    }
    cmp(eax, descriptor.count);
    jae(trap_exit(Trap::IndexOutOfRange));
    const std::uint32_t size = descriptor.element_size;
    if (size == 1 || size == 2 || size == 4 || size == 8) {
        return address_of(array_field, descriptor.offset) + rax * static_cast<int>(size);
    }
    imul(rax, rax, static_cast<int>(size));
    return address_of(array_field, descriptor.offset) + rax;
}

void Translator::call_step(const Instruction& ins) {
    const std::size_t index = static_cast<std::size_t>(&ins - image_.code.data());
    mov(rdi, r15);
    mov(rsi, reinterpret_cast<std::size_t>(&out_.code_[index]));
    mov(rax, reinterpret_cast<std::size_t>(step_function(ins.opcode)));
    call(rax);
    cmp(eax, kStepTrap);
    Exit e = trap_here();
    e.trap_from_step = true;
    jae(exit(std::move(e)));
}

// --- The translation ---------------------------------------------------------------------------

void Translator::emit_entry_and_exit() {
    // enter(context, address): save the callee-saved registers, load the VM's, jump in.
    for (const auto* r : {&rbx, &rbp, &r12, &r13, &r14, &r15}) {
        push(*r);
    }
    sub(rsp, 8); // the stack 16-byte aligned for step functions
    mov(r15, rdi);
    mov(qword[r15 + kMachineStack], rsp);
    xor_(ebp, ebp);
    mov(r12, qword[r15 + context_base(Base::Static)]);
    mov(r13, qword[r15 + context_base(Base::Frame)]);
    mov(r14, qword[r15 + context_base(Base::Self)]);
    mov(rbx, qword[r15 + kRemaining]);
    jmp(rsi);

    L(exit_common_);
    mov(qword[r15 + kRemaining], rbx);
    mov(qword[r15 + context_base(Base::Frame)], r13);
    mov(qword[r15 + context_base(Base::Self)], r14);
    mov(rsp, qword[r15 + kMachineStack]);
    add(rsp, 8);
    for (const auto* r : {&r15, &r14, &r13, &r12, &rbp, &rbx}) {
        pop(*r);
    }
    ret();
}

void Translator::emit_exits() {
    for (Exit& e : exits_) {
        L(e.label);
        if (e.charge != 0) {
            sub(rbx, static_cast<std::uint32_t>(e.charge));
        }
        if (e.kind == ExitKind::Trapped) {
            if (e.trap_from_step) {
                sub(eax, kStepTrap);
                mov(dword[r15 + kExitTrap], eax);
            } else {
                mov(dword[r15 + kExitTrap], static_cast<std::uint32_t>(e.trap));
            }
        }
        if (e.pc_in_ecx) {
            mov(dword[r15 + kExitPc], ecx);
        } else {
            mov(dword[r15 + kExitPc], e.pc);
        }
        mov(dword[r15 + kExitPou], e.pou);
        mov(dword[r15 + kExitKind], static_cast<std::uint32_t>(e.kind));
        jmp(exit_common_);
    }
}

void Translator::translate() {
    emit_entry_and_exit();
    const std::vector<bool> starts = block_starts(image_);
    for (std::uint32_t p = 0; p < image_.pous.size(); ++p) {
        pou_index_ = p;
        pou_ = &image_.pous[p];
        for (index_ = pou_->code_begin; index_ < pou_->code_end; ++index_) {
            if (starts[index_]) {
                segment_ = index_;
                stored_rax_.reset();
                stored_xmm0_.reset();
            }
            held_rax_ = std::exchange(stored_rax_, std::nullopt);
            held_xmm0_ = std::exchange(stored_xmm0_, std::nullopt);
            L(labels_[index_]);
            const Instruction& ins = image_.code[index_];
            emit_instruction(ins);
            if (!ends_block(ins) && starts[index_ + 1]) {
                charge_block(); // falls into the next block
            }
        }
    }
    emit_exits();
    readyRE();
    out_.enter_ = getCode<CompiledCode::Entry>();
    out_.entries_.assign(image_.code.size(), nullptr);
    for (const Pou& pou : image_.pous) {
        for (auto i = pou.code_begin; i < pou.code_end; ++i) {
            out_.entries_[i] = labels_[i].getAddress();
        }
    }
    labels_.clear();
    exits_.clear();
}

void Translator::emit_instruction(const Instruction& ins) {
    bool emitted = false;
    switch (ins.opcode) {
#define VM_TRANSLATE(name, family, T1, T2, ...)                                                    \
    case Opcode::name:                                                                             \
        emitted = emit_##family<T1, T2>(ins);                                                      \
        break;
        EPOSP_VM_OPCODES(VM_TRANSLATE)
#undef VM_TRANSLATE
    }
    if (emitted) {
        return;
    }
    call_step(ins);
    if (auto target = branch_target(ins)) {
        charge_block();
        branch(*target, [&](Xbyak::Label& skip) {
            cmp(eax, kStepTaken);
            jne(skip);
        });
    }
}

// --- Jumps, calls, returns ---------------------------------------------------------------------

template <typename T, typename R>
bool Translator::emit_Nop(const Instruction&) {
    return true;
}

template <typename T, typename R>
bool Translator::emit_Jmp(const Instruction& ins) {
    charge_block();
    jump_to(ins.a);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Jt(const Instruction& ins) {
    charge_block();
    cmp(at(ins.a, 1), 0);
    branch_if(Cond::NE, ins.b);
    return true;
}

template <typename T, typename R>
bool Translator::emit_Jf(const Instruction& ins) {
    charge_block();
    cmp(at(ins.a, 1), 0);
    branch_if(Cond::E, ins.b);
    return true;
}

template <typename T, typename R>
bool Translator::emit_JtX(const Instruction& ins) {
    const auto address = element(ins, ins.a, ins.b);
    charge_block();
    cmp(byte[address], 0);
    branch_if(Cond::NE, ins.c);
    return true;
}

template <typename T, typename R>
bool Translator::emit_JfX(const Instruction& ins) {
    const auto address = element(ins, ins.a, ins.b);
    charge_block();
    cmp(byte[address], 0);
    branch_if(Cond::E, ins.c);
    return true;
}

// The selector meets the table's low end on the 32-bit circle, as in the interpreter; the
// target is known only at run time, so the jump goes through the entry table.
template <typename T, typename R>
bool Translator::emit_JTab(const Instruction& ins) {
    const JumpTable& table = image_.jump_tables[ins.b];
    charge_block();
    if constexpr (sizeof(T) == 2) {
        std::is_signed_v<T> ? movsx(eax, at(ins.a, 2)) : movzx(eax, at(ins.a, 2));
    } else {
        mov(eax, at(ins.a, 4));
    }
    sub(eax, static_cast<std::uint32_t>(table.low));
    Xbyak::Label outside;
    Xbyak::Label go;
    cmp(eax, static_cast<std::uint32_t>(table.targets.size()));
    jae(outside);
    mov(rdx, reinterpret_cast<std::size_t>(out_.jump_targets_[ins.b].data()));
    mov(ecx, dword[rdx + rax * 4]);
    jmp(go);
    L(outside);
    mov(ecx, ins.c);
    L(go);
    test(rbx, rbx);
    Exit e;
    e.kind = ExitKind::Suspended;
    e.pou = pou_index_;
    e.pc_in_ecx = true;
    js(exit(std::move(e)));
    mov(rdx, qword[r15 + kEntries]);
    jmp(qword[rdx + rcx * 8]);
    return true;
}

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

// --- Data ----------------------------------------------------------------------------------------

template <typename T, typename R>
bool Translator::emit_NotB(const Instruction& ins) {
    cmp(at(ins.b, 1), 0);
    sete(al);
    mov(at(ins.a, 1), al);
    return true;
}

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

template <typename T, typename Operation>
bool Translator::binary(const Instruction& ins, Operation&& operation) {
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
bool Translator::float_binary(const Instruction& ins, Operation&& operation) {
    float_load<T>(ins.b);
    operation(xmm0, at(ins.c, sizeof(T)));
    float_store<T>(ins.a);
    return true;
}

template <typename T, typename Operation>
bool Translator::unary(const Instruction& ins, Operation&& operation) {
    load(rax, ins.b, sizeof(T), false);
    operation(work(rax, sizeof(T)));
    store(ins.a, sizeof(T), rax);
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

// --- Comparisons ---------------------------------------------------------------------------------

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

// [A] += step, then loop while [A] <= [B] (step > 0) or [A] >= [B], compared as T.
template <typename T, typename R>
bool Translator::emit_For(const Instruction& ins) {
    constexpr int bytes = sizeof(T);
    const auto step = static_cast<std::int16_t>(ins.aux);
    charge_block();
    load(rax, ins.a, bytes, false);
    add(work(rax, bytes), step);
    store(ins.a, bytes, rax);
    if constexpr (bytes < 4) {
        std::is_signed_v<T> ? movsx(eax, part(rax, bytes)) : movzx(eax, part(rax, bytes));
    }
    const Cond cond =
        compare<T>(ins.a, ins.b, step > 0 ? Cond::LE : Cond::GE, step > 0 ? Cond::BE : Cond::AE);
    branch_if(cond, ins.c);
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

// --- Reals and conversions ----------------------------------------------------------------------

template <typename T, typename R>
bool Translator::emit_Sqrt(const Instruction& ins) {
    sizeof(T) == 4 ? sqrtss(xmm0, at(ins.b, 4)) : sqrtsd(xmm0, at(ins.b, 8));
    float_store<T>(ins.a);
    return true;
}

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

// --- Entry point -------------------------------------------------------------------------------

std::shared_ptr<const CompiledCode> compile(const Image& image) {
    std::shared_ptr<CompiledCode> code(new CompiledCode());
    code->code_ = image.code;
    for (const JumpTable& table : image.jump_tables) {
        code->jump_targets_.push_back(table.targets);
    }
    for (const Pou& pou : image.pous) {
        code->frame_sizes_.push_back(pou.frame_size);
    }
    try {
        auto translator = std::make_unique<Translator>(image, *code);
        translator->translate();
        code->generator_ = std::move(translator);
    } catch (const Xbyak::Error&) {
        return nullptr; // e.g. no executable memory: the interpreter runs the program
    }
    return code;
}

} // namespace eposp::vm::jit
