#include "interpreter.hpp"

#include "instruction_semantics.hpp"
#include "run_end.hpp"

#include <algorithm>

// The dispatch loop. Every handler is one family macro (VM_EXEC_<family>) applied to the types
// of the opcode list, so adding a type or an opcode never means a new hand-written handler.
// With GCC or Clang each handler jumps straight to the next one through a label table
// (computed goto, one indirect branch per handler); otherwise a switch in a loop.

namespace eposp::vm::detail {
namespace {

// The loop's exits are plain functions of values: a lambda capturing the loop's variables by
// reference would force `ip` into memory for the whole loop.
std::uint64_t executed_in_run(std::uint64_t limit, std::int64_t remaining) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(limit) - remaining);
}

// kCoverage: the loop also counts every instruction it dispatches and every outcome of a
// branch point (coverage_counters.hpp). A separate instantiation, so the loop without it has
// no test per instruction.
template <bool kCoverage>
RunState run(const Program& program, std::span<std::uint8_t> memory, TaskState& task,
             std::uint64_t slice, CoverageCounters* coverage) {
    const Image& image = program.image();
    const Instruction* const code = image.code.data();
    const Pou* const pous = image.pous.data();
    const ArrayDescriptor* const arrays = image.arrays.data();
    const JumpTable* const jump_tables = image.jump_tables.data();
    std::uint8_t* const mem = memory.data();
    const std::uint64_t mem_size = memory.size();

    // Restore the saved activation.
    std::uint32_t pou = task.current.pou;
    std::uint8_t* base[4];
    activation_bases(base, mem, task.current, pous[pou].frame_size);
    const Instruction* ip = code + task.current.pc;

    // Instruction counting: `segment` is where the current straight-line run started; at each
    // taken jump, call and return the run's length is charged, so the count is exact without
    // a counter update per instruction.
    const std::uint64_t limit = begin_run(task, slice);
    std::int64_t remaining = static_cast<std::int64_t>(limit);
    const Instruction* segment = ip;
    Trap trap = Trap::DivisionByZero;
    std::uint64_t* const executed = kCoverage ? coverage->executed.data() : nullptr;
    const std::uint32_t* const first_outcome = kCoverage ? coverage->first_outcome.data() : nullptr;
    std::uint64_t* const outcomes = kCoverage ? coverage->outcomes.data() : nullptr;

// Outcome `n` of the branch point at ip.
#define VM_COUNT_OUTCOME(n)                                                                        \
    do {                                                                                           \
        if constexpr (kCoverage) {                                                                 \
            ++outcomes[first_outcome[ip - code] + (n)];                                            \
        }                                                                                          \
    } while (false)
#define VM_COUNT_DISPATCH()                                                                        \
    do {                                                                                           \
        if constexpr (kCoverage) {                                                                 \
            ++executed[ip - code];                                                                 \
        }                                                                                          \
    } while (false)
#define VM_CHARGE() (remaining -= (ip - segment) + 1)
#define VM_TRAP(kind)                                                                              \
    do {                                                                                           \
        trap = (kind);                                                                             \
        goto trapped;                                                                              \
    } while (false)
// A safe point: charge the run, continue at `target`, and stop there if the slice is used up.
#define VM_JUMP(target)                                                                            \
    do {                                                                                           \
        VM_CHARGE();                                                                               \
        ip = code + (target);                                                                      \
        segment = ip;                                                                              \
        if (remaining < 0) {                                                                       \
            goto slice_used;                                                                       \
        }                                                                                          \
        VM_DISPATCH();                                                                             \
    } while (false)
#define VM_BRANCH_IF(condition, target)                                                            \
    do {                                                                                           \
        if (condition) {                                                                           \
            VM_COUNT_OUTCOME(0);                                                                   \
            VM_JUMP(target);                                                                       \
        }                                                                                          \
        VM_COUNT_OUTCOME(1);                                                                       \
        VM_NEXT();                                                                                 \
    } while (false)
#define VM_ENTER(callee_index, self_pointer)                                                       \
    do {                                                                                           \
        const Pou& callee = pous[callee_index];                                                    \
        const auto frame = static_cast<std::uint32_t>(base[3] - mem);                              \
        if (task.depth == kMaxCallDepth ||                                                         \
            std::uint64_t{frame} + callee.frame_size + callee.out_size > task.stack_end) {         \
            VM_TRAP(Trap::StackOverflow);                                                          \
        }                                                                                          \
        task.calls[task.depth++] = Activation{static_cast<std::uint32_t>(ip - code) + 1, pou,      \
                                              static_cast<std::uint32_t>(base[1] - mem),           \
                                              static_cast<std::uint32_t>(base[2] - mem)};          \
        pou = (callee_index);                                                                      \
        base[1] = base[3];                                                                         \
        base[2] = (self_pointer);                                                                  \
        base[3] = base[1] + callee.frame_size;                                                     \
        VM_JUMP(callee.code_begin);                                                                \
    } while (false)

#define VM_EXEC_Nop(T1, T2) VM_NEXT();
#define VM_EXEC_Jmp(T1, T2) VM_JUMP(ip->a);
#define VM_EXEC_JTab(T1, T2)                                                                       \
    {                                                                                              \
        const JumpTable& table = jump_tables[ip->b];                                               \
        const auto entry = static_cast<std::uint32_t>(static_cast<std::int64_t>(load<T1>(A))) -    \
                           static_cast<std::uint32_t>(table.low);                                  \
        VM_COUNT_OUTCOME(std::min<std::size_t>(entry, table.targets.size()));                      \
        VM_JUMP(entry < table.targets.size() ? table.targets[entry] : ip->c);                      \
    }
#define VM_EXEC_Call(T1, T2) VM_ENTER(ip->a, base[2]);
#define VM_EXEC_CallFb(T1, T2) VM_ENTER(ip->b, A);
#define VM_EXEC_CallFbP(T1, T2)                                                                    \
    {                                                                                              \
        std::uint8_t* instance;                                                                    \
        VM_DEREF(A, 0, pous[ip->b].instance_size, instance);                                       \
        VM_ENTER(ip->b, instance);                                                                 \
    }
#define VM_EXEC_CallNative(T1, T2)                                                                 \
    {                                                                                              \
        if (!call_native(program, ip->a, B, memory, task,                                          \
                         static_cast<std::uint32_t>(ip - code))) {                                 \
            VM_TRAP(Trap::NativeError);                                                            \
        }                                                                                          \
        VM_CHARGE();                                                                               \
        segment = ip + 1;                                                                          \
        if (remaining < 0) {                                                                       \
            ++ip;                                                                                  \
            goto slice_used;                                                                       \
        }                                                                                          \
        VM_NEXT();                                                                                 \
    }
#define VM_EXEC_Ret(T1, T2)                                                                        \
    {                                                                                              \
        VM_CHARGE();                                                                               \
        if (task.depth == 0) {                                                                     \
            goto finished;                                                                         \
        }                                                                                          \
        const Activation& caller = task.calls[--task.depth];                                       \
        pou = caller.pou;                                                                          \
        base[1] = mem + caller.frame;                                                              \
        base[2] = mem + caller.self;                                                               \
        base[3] = base[1] + pous[pou].frame_size;                                                  \
        ip = code + caller.pc;                                                                     \
        segment = ip;                                                                              \
        VM_DISPATCH();                                                                             \
    }

#define VM_HANDLER(name, family, T1, T2, aux, a, b, c)                                             \
    VM_CASE(name) {                                                                                \
        VM_EXEC_##family(T1, T2)                                                                   \
    }

#if defined(__GNUC__) && !defined(EPOSP_VM_PORTABLE_DISPATCH)
// Label addresses and computed goto are the GNU extension this dispatch exists for.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#define VM_LABEL_ADDRESS(name, ...) &&handle_##name,
    static constexpr void* kHandlers[] = {EPOSP_VM_OPCODES(VM_LABEL_ADDRESS)};
#undef VM_LABEL_ADDRESS
#define VM_CASE(name) handle_##name:
#define VM_DISPATCH()                                                                              \
    do {                                                                                           \
        VM_COUNT_DISPATCH();                                                                       \
        goto* kHandlers[static_cast<std::uint16_t>(ip->opcode)];                                   \
    } while (false)
#define VM_NEXT()                                                                                  \
    do {                                                                                           \
        ++ip;                                                                                      \
        VM_DISPATCH();                                                                             \
    } while (false)
    VM_DISPATCH();
    EPOSP_VM_OPCODES(VM_HANDLER)
#pragma GCC diagnostic pop
#else
// Every handler leaves by goto (a `continue` inside the macros' do-while would not reach the
// loop), and the verifier admits only known opcodes, so control never leaves the switch.
#define VM_CASE(name) case Opcode::name:
#define VM_DISPATCH() goto dispatch
#define VM_NEXT()                                                                                  \
    do {                                                                                           \
        ++ip;                                                                                      \
        goto dispatch;                                                                             \
    } while (false)
dispatch:
    VM_COUNT_DISPATCH();
    switch (ip->opcode) { EPOSP_VM_OPCODES(VM_HANDLER) }
#endif

trapped:
    VM_CHARGE();
    return end_faulted(task, image, executed_in_run(limit, remaining), trap, pou,
                       static_cast<std::uint32_t>(ip - code));

slice_used:
    return end_suspended(task, image, executed_in_run(limit, remaining),
                         Activation{static_cast<std::uint32_t>(ip - code), pou,
                                    static_cast<std::uint32_t>(base[1] - mem),
                                    static_cast<std::uint32_t>(base[2] - mem)});

finished:
    return end_finished(task, executed_in_run(limit, remaining));
}

} // namespace

RunState execute(const Program& program, std::span<std::uint8_t> memory, TaskState& task,
                 std::uint64_t slice, CoverageCounters* coverage) {
    return coverage != nullptr ? run<true>(program, memory, task, slice, coverage)
                               : run<false>(program, memory, task, slice, nullptr);
}

} // namespace eposp::vm::detail
