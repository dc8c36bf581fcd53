#include "context_offsets.hpp"
#include "translator.hpp"

// Leaving compiled code (exits for traps, suspensions and the end of a run), conditions, the
// taken side of a branch, and the call of a step function.

namespace eposp::vm::jit {

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

} // namespace eposp::vm::jit
