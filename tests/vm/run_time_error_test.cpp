// Run-time errors stop the task with a diagnostic naming the POU and the source line, and
// leave the machine usable.

#include "vm_harness.hpp"

namespace eposp::vm::test {
namespace {

struct TrapCase {
    const char* name;
    Trap trap;
    std::string message;
    void (*emit)(Builder&); ///< Main's faulting instruction, emitted at line 7
};

void PrintTo(const TrapCase& c, std::ostream* os) {
    *os << c.name;
}

class RunTimeError : public ::testing::TestWithParam<TrapCase> {};

TEST_P(RunTimeError, StopsTheTaskNamingPouAndLine) {
    const auto& c = GetParam();
    Harness h;
    h.builder.line(6);
    h.builder.emit(Opcode::Ldi32, self(0), Operand::imm(1));
    h.builder.line(7);
    c.emit(h.builder);
    h.builder.line(8);
    h.builder.emit(Opcode::Ldi32, self(0), Operand::imm(2));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Faulted);
    EXPECT_EQ(h.machine->task(0).fault.trap, c.trap);
    EXPECT_EQ(h.machine->describe_fault(0), c.message);
    EXPECT_EQ(h.get<std::int32_t>(0), 1) << "nothing after the fault ran";
}

INSTANTIATE_TEST_SUITE_P(
    Traps, RunTimeError,
    ::testing::Values(
        TrapCase{"IntegerDivisionByZero", Trap::DivisionByZero,
                 "division by zero in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::DivI32, self(8), self(8), self(12));
                 }},
        TrapCase{"ModuloByZero", Trap::DivisionByZero, "division by zero in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::ModU16, self(8), self(8), self(12));
                 }},
        TrapCase{"IndexAboveUpperBound", Trap::IndexOutOfRange,
                 "array index out of range in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::Ldi32, self(4), Operand::imm(10));
                     b.emit(Opcode::Ldx32, self(8), self(16), self(4), b.array({0, 10, 4}));
                 }},
        TrapCase{"IndexBelowLowerBound", Trap::IndexOutOfRange,
                 "array index out of range in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::Stx8, self(16), self(4), self(8), b.array({1, 10, 1}));
                 }},
        TrapCase{"TestedElementOutOfRange", Trap::IndexOutOfRange,
                 "array index out of range in Main at line 7",
                 [](Builder& b) {
                     const auto end = b.label();
                     b.emit(Opcode::Ldi32, self(4), Operand::imm(10));
                     b.jump(Opcode::JtX, end, self(16), self(4), b.array({0, 10, 1}));
                     b.bind(end);
                 }},
        TrapCase{"NullDereference", Trap::NullDereference, "NULL dereference in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::Ldp32, self(8), self(16), Operand::imm(0));
                 }},
        TrapCase{"PointerPastMemory", Trap::InvalidAddress, "invalid address in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::Ldi64, self(16), Operand::imm(0xFFFFFFF0),
                            Operand::imm(0xFFFFFFFF));
                     b.emit(Opcode::Stp64, self(16), self(8), Operand::imm(32));
                 }},
        TrapCase{"NullFbInstance", Trap::NullDereference, "NULL dereference in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::CallFbP, self(16), Operand::imm(0));
                 }},
        // An element of an array behind a NULL pointer (an unbound VAR_IN_OUT array): the
        // element's address is past the NULL guard, but it is no element of anything.
        TrapCase{"ElementOfANullArray", Trap::NullDereference, "NULL dereference in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::Ldi32, self(4), Operand::imm(3));
                     b.emit(Opcode::IdxAP, self(24), self(16), self(4), b.array({0, 4, 4}));
                     b.emit(Opcode::Stp32, self(24), self(8), Operand::imm(0));
                 }},
        TrapCase{"ValueAboveItsSubrange", Trap::SubrangeViolation,
                 "value out of subrange in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::Ldi16, self(4), Operand::imm(101));
                     b.emit(Opcode::Ldi32, self(8), Operand::imm(100 << 16)); // bounds 0..100
                     b.emit(Opcode::RangeI16, self(4), self(8));
                 }},
        TrapCase{"ValueBelowItsSubrange", Trap::SubrangeViolation,
                 "value out of subrange in Main at line 7",
                 [](Builder& b) {
                     b.emit(Opcode::Ldi64, self(4), Operand::imm(0xFFFFFFFF),
                            Operand::imm(0xFFFFFFFF));
                     b.emit(Opcode::Ldi64, self(16), Operand::imm(0));
                     b.emit(Opcode::Ldi64, self(24), Operand::imm(5));
                     b.emit(Opcode::RangeI64, self(4), self(16));
                 }},
        TrapCase{"IndexOutsideAVariableLengthDimension", Trap::IndexOutOfRange,
                 "array index out of range in Main at line 7", [](Builder& b) {
                     b.emit(Opcode::Ldi32, self(16), Operand::imm(-2)); // bounds -2..1
                     b.emit(Opcode::Ldi32, self(20), Operand::imm(4));
                     b.emit(Opcode::Ldi32, self(4), Operand::imm(2));
                     b.emit(Opcode::IdxDim, self(8), self(16), self(4));
                 }}));

TEST(RunTimeError, AnIndexInsideAVariableLengthDimensionCountsFromItsLowerBound) {
    Harness h;
    h.builder.emit(Opcode::Ldi32, self(16), Operand::imm(-2)); // bounds -2..1
    h.builder.emit(Opcode::Ldi32, self(20), Operand::imm(4));
    h.builder.emit(Opcode::Ldi32, self(4), Operand::imm(1));
    h.builder.emit(Opcode::IdxDim, self(8), self(16), self(4));
    h.builder.emit(Opcode::Ldi32, self(4), Operand::imm(-2));
    h.builder.emit(Opcode::IdxDim, self(12), self(16), self(4));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(8), 3);
    EXPECT_EQ(h.get<std::int32_t>(12), 0);
}

TEST(RunTimeError, ValuesOnTheBoundsOfASubrangePass) {
    Harness h;
    h.builder.emit(Opcode::Ldi8, self(0), Operand::imm(200));
    h.builder.emit(Opcode::Ldi16, self(2), Operand::imm(200 | 255 << 8)); // USINT 200..255
    h.builder.emit(Opcode::RangeU8, self(0), self(2));
    h.builder.emit(Opcode::Ldi8, self(0), Operand::imm(255));
    h.builder.emit(Opcode::RangeU8, self(0), self(2));
    h.builder.emit(Opcode::Ldi32, self(4), Operand::imm(7));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(4), 7);
}

TEST(RunTimeError, FaultInAFunctionNamesTheFunctionAndItsLine) {
    Harness h;
    const auto helper = h.builder.declare_pou("Helper", PouKind::Function);
    h.builder.line(3);
    h.builder.emit(Opcode::Call, Operand::imm(helper));
    h.builder.emit(Opcode::Ret);
    h.end_main(0, 8);
    h.builder.begin_body(helper);
    h.builder.line(21);
    h.builder.emit(Opcode::Ldi32, Operand::local(0), Operand::imm(5));
    h.builder.line(22);
    h.builder.emit(Opcode::DivI32, Operand::local(0), Operand::local(0), Operand::local(4));
    h.builder.emit(Opcode::Ret);
    h.builder.end_body(8);
    ASSERT_EQ(h.run(), RunState::Faulted);
    EXPECT_EQ(h.machine->describe_fault(0), "division by zero in Helper at line 22");
}

// Main calls Again, which calls itself at line 4 with a frame of `frame_size` bytes.
void emit_recursion(Harness& h, std::uint32_t frame_size) {
    const auto self_call = h.builder.declare_pou("Again", PouKind::Function);
    h.builder.emit(Opcode::Call, Operand::imm(self_call));
    h.builder.emit(Opcode::Ret);
    h.end_main(0, 0);
    h.builder.begin_body(self_call);
    h.builder.line(4);
    h.builder.emit(Opcode::Call, Operand::imm(self_call));
    h.builder.emit(Opcode::Ret);
    h.builder.end_body(frame_size);
}

TEST(RunTimeError, RunawayRecursionIsAStackOverflow) {
    Harness h;
    emit_recursion(h, 64);
    ASSERT_EQ(h.run(), RunState::Faulted);
    EXPECT_EQ(h.machine->describe_fault(0), "stack overflow in Again at line 4");
}

// With empty frames the stack never fills: the call depth limit stops the recursion, and the
// task runs again afterwards (compiled code leaves from 256 machine calls deep).
TEST(RunTimeError, RecursionWithoutFramesStopsAtTheCallDepthLimit) {
    Harness h;
    emit_recursion(h, 0);
    ASSERT_EQ(h.run(), RunState::Faulted);
    EXPECT_EQ(h.machine->describe_fault(0), "stack overflow in Again at line 4");
    EXPECT_EQ(h.machine->task(0).depth, kMaxCallDepth);
    EXPECT_EQ(h.machine->run_cycle(0), RunState::Faulted);
}

TEST(RunTimeError, FailingNativeFunctionStopsTheTaskWithItsReason) {
    Harness h;
    h.natives.add("FAIL", NativeSignature{}, [](NativeArgs& args) { args.fail("no axis"); });
    h.builder.line(9);
    h.builder.emit(Opcode::CallNative, Operand::imm(h.builder.import("FAIL", NativeSignature{})),
                   Operand::out(0));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Faulted);
    EXPECT_EQ(h.machine->describe_fault(0), "native function failed: no axis in Main at line 9");
}

TEST(RunTimeError, TaskRunsAgainAfterAFaultOnceTheCauseIsGone) {
    Harness h;
    h.builder.emit(Opcode::DivI32, self(0), self(0), self(4));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Faulted);
    h.set<std::int32_t>(4, 1);
    EXPECT_EQ(h.machine->run_cycle(0), RunState::Finished);
}

} // namespace
} // namespace eposp::vm::test
