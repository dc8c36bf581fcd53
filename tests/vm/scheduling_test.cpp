// The watchdog budget, exact instruction counting, and suspending a task at a safe point so
// that another task can run before it resumes.

#include "vm_harness.hpp"

namespace eposp::vm::test {
namespace {

TEST(Watchdog, BudgetStopsAnEndlessLoop) {
    Harness h;
    h.builder.line(12);
    auto forever = h.builder.label();
    h.builder.bind(forever);
    h.builder.emit(Opcode::AddI32, self(0), self(0), imm(1));
    h.builder.jump(Opcode::Jmp, forever);
    h.end_main();
    ASSERT_EQ(h.load(), "");
    h.machine->set_budget(0, 10'000);
    ASSERT_EQ(h.machine->run_cycle(0), RunState::Faulted);
    EXPECT_EQ(h.machine->describe_fault(0), "instruction budget exceeded in Main at line 12");
    EXPECT_GE(h.machine->task(0).executed, 10'000U);
    EXPECT_LE(h.machine->task(0).executed, 10'002U) << "stops at the first safe point after it";
    EXPECT_EQ(h.get<std::int32_t>(0), 5'001);
}

TEST(Watchdog, CountsEveryInstructionExactly) {
    Harness h;
    auto loop = h.builder.label();
    h.init<std::int32_t>(4, 10);
    h.builder.emit(Opcode::Nop); // 1
    h.builder.bind(loop);        // 10 iterations of 3
    h.builder.emit(Opcode::AddI32, self(0), self(0), imm(1));
    h.builder.emit(Opcode::Nop);
    h.builder.jump(Opcode::JLtI32, loop, self(0), self(4));
    h.builder.emit(Opcode::Ret); // 1
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.machine->task(0).executed, 1U + 10 * 3 + 1);
}

// Sorts 64 DINTs (bubble sort over an array with a function call per comparison), so that a
// suspension can land in a nested call, inside either loop.
void emit_sorting_program(Harness& h) {
    auto& b = h.builder;
    const auto greater = b.declare_pou("Greater", PouKind::Function);
    const auto a = b.array({0, 64, 4});
    constexpr std::uint32_t kI = 0, kJ = 4, kX = 8, kY = 12, kLast = 16, kSeed = 20, kJ1 = 24;
    constexpr std::uint32_t kArray = 64;
    h.init<std::int32_t>(kLast, 63);
    auto fill = b.label(), outer = b.label(), inner = b.label(), no_swap = b.label();
    b.emit(Opcode::Ldi32, self(kI), Operand::imm(0));
    b.bind(fill); // a[i] := seed := (seed * 75 + 74) MOD 1000
    b.emit(Opcode::Ldi32, self(kX), Operand::imm(75));
    b.emit(Opcode::Mul32, self(kSeed), self(kSeed), self(kX));
    b.emit(Opcode::AddI32, self(kSeed), self(kSeed), imm(74));
    b.emit(Opcode::Ldi32, self(kX), Operand::imm(1000));
    b.emit(Opcode::ModI32, self(kSeed), self(kSeed), self(kX));
    b.emit(Opcode::Stx32, self(kArray), self(kI), self(kSeed), a);
    b.emit(Opcode::AddI32, self(kI), self(kI), imm(1));
    b.jump(Opcode::JLeI32, fill, self(kI), self(kLast));
    b.emit(Opcode::Ldi32, self(kI), Operand::imm(0));
    b.bind(outer);
    b.emit(Opcode::Ldi32, self(kJ), Operand::imm(0));
    b.bind(inner);
    b.emit(Opcode::AddI32, self(kJ1), self(kJ), imm(1));
    b.emit(Opcode::Ldx32, Operand::out(0), self(kArray), self(kJ), a);
    b.emit(Opcode::Ldx32, Operand::out(4), self(kArray), self(kJ1), a);
    b.emit(Opcode::Call, Operand::imm(greater));
    b.jump(Opcode::Jf, no_swap, Operand::out(8));
    b.emit(Opcode::Stx32, self(kArray), self(kJ), Operand::out(4), a);
    b.emit(Opcode::Stx32, self(kArray), self(kJ1), Operand::out(0), a);
    b.bind(no_swap);
    b.emit(Opcode::Mov32, self(kY), self(kLast));
    b.emit(Opcode::Sub32, self(kY), self(kY), self(kI));
    b.emit(Opcode::AddI32, self(kJ), self(kJ), imm(1));
    b.jump(Opcode::JLtI32, inner, self(kJ), self(kY));
    b.emit(Opcode::AddI32, self(kI), self(kI), imm(1));
    b.jump(Opcode::JLtI32, outer, self(kI), self(kLast));
    b.emit(Opcode::Ret);
    h.end_main(0, 12);
    b.begin_body(greater);
    b.emit(Opcode::LtI32, Operand::local(8), Operand::local(4), Operand::local(0));
    b.emit(Opcode::Ret);
    b.end_body(12);
}

std::vector<std::int32_t> sorted_array(const Harness& h) {
    std::vector<std::int32_t> values(64);
    std::memcpy(values.data(), h.machine->memory().data() + h.instance + 64, 64 * 4);
    return values;
}

TEST(Suspension, ResumingAtSafePointsGivesTheUninterruptedResult) {
    Harness reference;
    emit_sorting_program(reference);
    ASSERT_EQ(reference.run(), RunState::Finished);
    const auto expected = sorted_array(reference);
    ASSERT_TRUE(std::is_sorted(expected.begin(), expected.end()));

    for (const std::uint64_t slice : {1, 7, 100, 1000}) {
        Harness h;
        emit_sorting_program(h);
        ASSERT_EQ(h.load(), "");
        h.machine->start(0, 0);
        int suspensions = 0;
        RunState state;
        while ((state = h.machine->run(0, slice)) == RunState::Suspended) {
            ++suspensions;
        }
        ASSERT_EQ(state, RunState::Finished) << "slice " << slice;
        EXPECT_GT(suspensions, 0);
        EXPECT_EQ(sorted_array(h), expected) << "slice " << slice;
        EXPECT_EQ(h.machine->task(0).executed, reference.machine->task(0).executed);
    }
}

TEST(Suspension, AnotherTaskRunsOnItsOwnStackWhileTheFirstIsSuspended) {
    Harness h;
    emit_sorting_program(h);
    // A second task, "Fast" (task 0; Main's own task is added by load() as task 1), runs the
    // same program on a second instance and preempts Main's task in the middle of its run.
    const auto second_instance = h.builder.allocate(Harness::kInstanceSize, 8);
    const std::uint8_t last[] = {63, 0, 0, 0};
    h.builder.initialise(second_instance + 16, last);
    h.builder.task(Task{.name = "Fast",
                        .kind = TaskKind::Cyclic,
                        .interval_ns = 100'000,
                        .stack_size = 4096,
                        .entries = {TaskEntry{h.main, second_instance}}});
    ASSERT_EQ(h.load(), "");
    h.machine->start(1, 0);
    ASSERT_EQ(h.machine->run(1, 500), RunState::Suspended);
    ASSERT_EQ(h.machine->run_cycle(0), RunState::Finished); // runs to completion in between
    while (h.machine->run(1, 500) == RunState::Suspended) {
    }
    ASSERT_EQ(h.machine->task(1).state, RunState::Finished);
    const auto first = sorted_array(h);
    EXPECT_TRUE(std::is_sorted(first.begin(), first.end()));
    EXPECT_EQ(std::memcmp(h.machine->memory().data() + second_instance + 64,
                          h.machine->memory().data() + h.instance + 64, 64 * 4),
              0);
}

} // namespace
} // namespace eposp::vm::test
