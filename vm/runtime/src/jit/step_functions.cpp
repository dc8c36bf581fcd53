#include "../instruction_semantics.hpp"
#include "step_context.hpp"

// One function per opcode, expanding the same family macros as the interpreter: compiled code
// calls these for the instructions it does not translate itself, so both engines share one
// definition of every operation.

namespace eposp::vm::jit {
namespace {

using namespace detail; // load, store, the value semantics (add, convert, divide...)

// The families the translator emits itself have no step function.
#define VM_EXEC_Jmp(T1, T2)
#define VM_EXEC_JTab(T1, T2)
#define VM_EXEC_Call(T1, T2)
#define VM_EXEC_CallFb(T1, T2)
#define VM_EXEC_CallFbP(T1, T2)
#define VM_EXEC_Ret(T1, T2)
#define VM_EXEC_Nop(T1, T2) VM_NEXT();
#define VM_EXEC_CallNative(T1, T2)                                                                 \
    if (!call_native(*context.program, ip->a, B, {mem, mem_size}, *context.task,                   \
                     static_cast<std::uint32_t>(ip - context.code))) {                             \
        VM_TRAP(Trap::NativeError);                                                                \
    }                                                                                              \
    VM_NEXT();

#define VM_NEXT() return kStepNext
#define VM_BRANCH_IF(condition, target) return (condition) ? kStepTaken : kStepNext
#define VM_TRAP(kind) return kStepTrap + static_cast<std::uint32_t>(kind)

#define VM_STEP_FUNCTION(name, family, T1, T2, aux, a, b, c)                                       \
    [[maybe_unused]] std::uint32_t step_##name(StepContext& context,                               \
                                               const Instruction& instruction) {                   \
        [[maybe_unused]] const Instruction* const ip = &instruction;                               \
        [[maybe_unused]] std::uint8_t* const* const base = context.base;                           \
        [[maybe_unused]] const ArrayDescriptor* const arrays = context.arrays;                     \
        [[maybe_unused]] std::uint8_t* const mem = context.mem;                                    \
        [[maybe_unused]] const std::uint64_t mem_size = context.mem_size;                          \
        VM_EXEC_##family(T1, T2) return kStepNext;                                                 \
    }
EPOSP_VM_OPCODES(VM_STEP_FUNCTION)

#define VM_STEP_ENTRY(name, family, ...) &step_##name,
constexpr StepFunction kStepFunctions[] = {EPOSP_VM_OPCODES(VM_STEP_ENTRY)};

bool translated_by_caller(Opcode op) {
    switch (op) {
    case Opcode::Jmp:
    case Opcode::JTabI16:
    case Opcode::JTabU16:
    case Opcode::JTab32:
    case Opcode::Call:
    case Opcode::CallFb:
    case Opcode::CallFbP:
    case Opcode::Ret:
        return true;
    default:
        return false;
    }
}

} // namespace

StepFunction step_function(Opcode op) {
    return translated_by_caller(op) ? nullptr : kStepFunctions[static_cast<std::uint16_t>(op)];
}

} // namespace eposp::vm::jit
