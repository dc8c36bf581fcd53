// Jumps, compare-and-branch, calls of functions and FB bodies, native functions.

#include "vm_harness.hpp"

#include <cmath>

namespace eposp::vm::test {
namespace {

// FOR i := 1 TO 100 DO sum := sum + i; END_FOR
TEST(ControlFlow, CountedLoopWithCompareAndBranch) {
    Harness h;
    constexpr std::uint32_t kI = 0, kSum = 4, kLimit = 8;
    h.init<std::int32_t>(kLimit, 100);
    auto loop = h.builder.label();
    h.builder.emit(Opcode::Ldi32, self(kI), Operand::imm(1));
    h.builder.bind(loop);
    h.builder.emit(Opcode::Add32, self(kSum), self(kSum), self(kI));
    h.builder.emit(Opcode::AddI32, self(kI), self(kI), imm(1));
    h.builder.jump(Opcode::JLeI32, loop, self(kI), self(kLimit));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(kSum), 5050);
}

// FOR i := 10 TO 1 BY -3 DO n := n + 1; last := i; END_FOR   (i = 10, 7, 4, 1)
TEST(ControlFlow, ForLoopBackEdgeCountsDown) {
    Harness h;
    constexpr std::uint32_t kI = 0, kLimit = 8, kN = 16, kLast = 24;
    h.init<std::int64_t>(kLimit, 1);
    auto body = h.builder.label();
    h.builder.emit(Opcode::Ldi64, self(kI), Operand::imm(10));
    h.builder.bind(body);
    h.builder.emit(Opcode::AddI16, self(kN), self(kN), imm(1));
    h.builder.emit(Opcode::Mov64, self(kLast), self(kI));
    h.builder.for_loop(Opcode::ForI64, body, self(kI), self(kLimit), -3);
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int16_t>(kN), 4);
    EXPECT_EQ(h.get<std::int64_t>(kLast), 1);
    EXPECT_EQ(h.get<std::int64_t>(kI), -2);
}

// FOR u := 250 TO 255 DO n := n + 1; END_FOR on a USINT: the step past 255 wraps to 0 and
// ends the loop (it never ended).
TEST(ControlFlow, ForLoopBackEdgeEndsAtTheTopOfItsType) {
    Harness h;
    constexpr std::uint32_t kU = 0, kLimit = 1, kN = 4;
    h.init<std::uint8_t>(kLimit, 255);
    auto body = h.builder.label();
    h.builder.emit(Opcode::Ldi8, self(kU), Operand::imm(250));
    h.builder.bind(body);
    h.builder.emit(Opcode::AddI32, self(kN), self(kN), imm(1));
    h.builder.for_loop(Opcode::ForU8, body, self(kU), self(kLimit), 1);
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(kN), 6);
    EXPECT_EQ(h.get<std::uint8_t>(kU), 0);
}

TEST(ControlFlow, ConditionalJumpsOnBool) {
    Harness h;
    h.init<std::uint8_t>(0, 1);
    auto skip_true = h.builder.label();
    auto skip_false = h.builder.label();
    h.builder.jump(Opcode::Jt, skip_true, self(0));
    h.builder.emit(Opcode::Ldi32, self(4), Operand::imm(111)); // skipped
    h.builder.bind(skip_true);
    h.builder.jump(Opcode::Jf, skip_false, self(0));
    h.builder.emit(Opcode::Ldi32, self(8), Operand::imm(222)); // runs
    h.builder.bind(skip_false);
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(4), 0);
    EXPECT_EQ(h.get<std::int32_t>(8), 222);
}

// IF (w AND 16#8000) <> 0 THEN ... and IF (w AND 16#0001) = 0 THEN ..., at full width.
TEST(ControlFlow, BitTestAndBranch) {
    Harness h;
    h.init<std::uint64_t>(0, 0x8000'0000'0000'8000);
    h.init<std::uint64_t>(8, 0x8000'0000'0000'0000);
    h.init<std::uint64_t>(16, 1);
    auto set = h.builder.label();
    auto high_set = h.builder.label();
    auto clear = h.builder.label();
    auto end = h.builder.label();
    h.builder.jump(Opcode::JTst16, set, self(0), self(16)); // 16#8000 AND 1: not taken
    h.builder.jump(Opcode::JTst64, high_set, self(0), self(8));
    h.builder.emit(Opcode::Ldi32, self(24), Operand::imm(111)); // skipped
    h.builder.bind(high_set);
    h.builder.jump(Opcode::JNTst32, clear, self(0), self(16)); // 16#8000 AND 1 = 0: taken
    h.builder.bind(set);
    h.builder.emit(Opcode::Ldi32, self(28), Operand::imm(222)); // skipped
    h.builder.bind(clear);
    h.builder.jump(Opcode::JNTst8, end, self(16), self(16));    // 1 AND 1 <> 0: not taken
    h.builder.emit(Opcode::Ldi32, self(32), Operand::imm(333)); // runs
    h.builder.bind(end);
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(24), 0);
    EXPECT_EQ(h.get<std::int32_t>(28), 0);
    EXPECT_EQ(h.get<std::int32_t>(32), 333);
}

// flags : ARRAY[1..3] OF BOOL := [FALSE, TRUE, FALSE]: IF flags[i] and IF NOT flags[i].
TEST(ControlFlow, TestArrayElementAndBranch) {
    Harness h;
    constexpr std::uint32_t kI = 0, kFlags = 4;
    h.init<std::uint8_t>(kFlags + 1, 1);
    h.init<std::int32_t>(kI, 2);
    const auto flags = h.builder.array({1, 3, 1});
    auto set = h.builder.label();
    auto clear = h.builder.label();
    auto end = h.builder.label();
    h.builder.jump(Opcode::JfX, clear, self(kFlags), self(kI), flags); // flags[2]: not taken
    h.builder.jump(Opcode::JtX, set, self(kFlags), self(kI), flags);   // taken
    h.builder.bind(clear);
    h.builder.emit(Opcode::Ldi32, self(8), Operand::imm(111)); // skipped
    h.builder.bind(set);
    h.builder.emit(Opcode::AddI32, self(kI), self(kI), imm(1));
    h.builder.jump(Opcode::JtX, end, self(kFlags), self(kI), flags); // flags[3]: not taken
    h.builder.emit(Opcode::Ldi32, self(12), Operand::imm(222));      // runs
    h.builder.bind(end);
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(8), 0);
    EXPECT_EQ(h.get<std::int32_t>(12), 222);
}

// FUNCTION Cube : DINT  VAR_INPUT x : DINT; END_VAR  (x at frame 0, result at frame 4)
std::uint32_t emit_cube(Builder& b) {
    const auto cube = b.declare_pou("Cube", PouKind::Function);
    b.begin_body(cube);
    b.emit(Opcode::Mul32, Operand::local(4), Operand::local(0), Operand::local(0));
    b.emit(Opcode::Mul32, Operand::local(4), Operand::local(4), Operand::local(0));
    b.emit(Opcode::Ret);
    b.end_body(8);
    return cube;
}

TEST(ControlFlow, FunctionCallsPassArgumentsThroughTheOutArea) {
    Harness h;
    // Main: r := Cube(3) + Cube(-2)   (the callee's pou index is known before its body)
    const auto cube = h.builder.declare_pou("Cube", PouKind::Function);
    h.builder.emit(Opcode::Ldi32, Operand::out(0), Operand::imm(3));
    h.builder.emit(Opcode::Call, Operand::imm(cube));
    h.builder.emit(Opcode::Mov32, self(0), Operand::out(4));
    h.builder.emit(Opcode::Ldi32, Operand::out(0), imm(-2));
    h.builder.emit(Opcode::Call, Operand::imm(cube));
    h.builder.emit(Opcode::Add32, self(0), self(0), Operand::out(4));
    h.builder.emit(Opcode::Ret);
    h.end_main(0, 8);
    h.builder.begin_body(cube);
    h.builder.emit(Opcode::Mul32, Operand::local(4), Operand::local(0), Operand::local(0));
    h.builder.emit(Opcode::Mul32, Operand::local(4), Operand::local(4), Operand::local(0));
    h.builder.emit(Opcode::Ret);
    h.builder.end_body(8);
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(0), 27 - 8);
}

TEST(ControlFlow, NestedCallsKeepEachFrame) {
    Harness h;
    // Main calls Outer(5); Outer calls Cube(x) and returns its own x + Cube(x).
    const auto outer = h.builder.declare_pou("Outer", PouKind::Function);
    h.builder.emit(Opcode::Ldi32, Operand::out(0), Operand::imm(5));
    h.builder.emit(Opcode::Call, Operand::imm(outer));
    h.builder.emit(Opcode::Mov32, self(0), Operand::out(4));
    h.builder.emit(Opcode::Ret);
    h.end_main(0, 8);
    const auto cube = emit_cube(h.builder);
    h.builder.begin_body(outer);
    h.builder.emit(Opcode::Mov32, Operand::out(0), Operand::local(0));
    h.builder.emit(Opcode::Call, Operand::imm(cube));
    h.builder.emit(Opcode::Add32, Operand::local(4), Operand::local(0), Operand::out(4));
    h.builder.emit(Opcode::Ret);
    h.builder.end_body(8, 8);
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(0), 5 + 125);
}

// FUNCTION_BLOCK Counter  VAR_INPUT step : DINT; END_VAR  VAR count : DINT; END_VAR
std::uint32_t emit_counter(Builder& b, std::uint32_t counter) {
    b.begin_body(counter);
    b.emit(Opcode::Add32, Operand::self(4), Operand::self(4), Operand::self(0));
    b.emit(Opcode::Ret);
    b.end_body(0);
    return counter;
}

TEST(ControlFlow, FbCallsRunTheBodyOnEachInstance) {
    Harness h;
    const auto counter = h.builder.declare_pou("Counter", PouKind::FunctionBlock, 8);
    // Main has two Counter instances at self+0 and self+8: a(step := 1); a(); b(step := 10);
    h.builder.emit(Opcode::Ldi32, self(0), Operand::imm(1));
    h.builder.emit(Opcode::CallFb, self(0), Operand::imm(counter));
    h.builder.emit(Opcode::CallFb, self(0), Operand::imm(counter));
    h.builder.emit(Opcode::Ldi32, self(8), Operand::imm(10));
    h.builder.emit(Opcode::CallFb, self(8), Operand::imm(counter));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    emit_counter(h.builder, counter);
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(4), 2);
    EXPECT_EQ(h.get<std::int32_t>(12), 10);
    ASSERT_EQ(h.machine->run_cycle(0), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(4), 4) << "instance data is static: it survives the cycle";
}

TEST(ControlFlow, FbCallThroughAPointerToAnArrayElement) {
    Harness h;
    const auto counter = h.builder.declare_pou("Counter", PouKind::FunctionBlock, 8);
    const auto fbs = h.builder.array({1, 3, 8}); // ARRAY[1..3] OF Counter at self+16
    // i := 3; fbs[i].step := 7; fbs[i]();
    h.builder.emit(Opcode::Ldi32, self(0), Operand::imm(3));
    h.builder.emit(Opcode::IdxA, self(8), self(16), self(0), fbs);
    h.builder.emit(Opcode::Ldi32, self(4), Operand::imm(7));
    h.builder.emit(Opcode::Stp32, self(8), self(4), Operand::imm(0));
    h.builder.emit(Opcode::CallFbP, self(8), Operand::imm(counter));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    emit_counter(h.builder, counter);
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(16 + 2 * 8 + 4), 7);
}

TEST(ControlFlow, NativeFunctionsReceiveArgumentsAndReturnAResult) {
    Harness h;
    const NativeSignature hypot{true, Scalar::F64, {Scalar::F64, Scalar::F64}};
    h.natives.add("HYPOT", hypot, [](NativeArgs& args) {
        args.set_result(std::hypot(args.get<double>(0), args.get<double>(1)));
    });
    const auto import = h.builder.import("HYPOT", hypot);
    h.init(0, 3.0);
    h.init(8, 4.0);
    h.builder.emit(Opcode::Mov64, Operand::out(parameter_offset(hypot, 0)), self(0));
    h.builder.emit(Opcode::Mov64, Operand::out(parameter_offset(hypot, 1)), self(8));
    h.builder.emit(Opcode::CallNative, Operand::imm(import), Operand::out(0));
    h.builder.emit(Opcode::Mov64, self(16), Operand::out(0));
    h.builder.emit(Opcode::Ret);
    h.end_main(0, argument_block_size(hypot));
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_DOUBLE_EQ(h.get<double>(16), 5.0);
}

TEST(ControlFlow, NativeFunctionBlockWorksOnItsInstanceThroughAPointer) {
    Harness h;
    // A native FB: its instance (a DINT counter) is passed by address and checked for range.
    const NativeSignature tick{false, Scalar::Bool, {Scalar::Ptr}};
    h.natives.add("TICK", tick, [](NativeArgs& args) {
        auto instance = args.memory(args.get<std::uint64_t>(0), 4);
        if (instance.empty()) {
            return args.fail("bad instance");
        }
        std::int32_t count;
        std::memcpy(&count, instance.data(), 4);
        ++count;
        std::memcpy(instance.data(), &count, 4);
    });
    const auto import = h.builder.import("TICK", tick);
    h.builder.emit(Opcode::Addr, Operand::out(0), self(32), Operand::imm(4));
    h.builder.emit(Opcode::CallNative, Operand::imm(import), Operand::out(0));
    h.builder.emit(Opcode::CallNative, Operand::imm(import), Operand::out(0));
    h.builder.emit(Opcode::Ret);
    h.end_main(0, 8);
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(32), 2);
}

TEST(ControlFlow, LinkRefusesMissingOrMismatchedNatives) {
    {
        Harness h;
        h.builder.import("NOPE", NativeSignature{});
        h.builder.emit(Opcode::Ret);
        h.end_main();
        EXPECT_EQ(h.load(), "native function NOPE is not available");
    }
    {
        Harness h;
        h.natives.add("F", NativeSignature{true, Scalar::F32, {}}, [](NativeArgs&) {});
        h.builder.import("F", NativeSignature{true, Scalar::F64, {}});
        h.builder.emit(Opcode::Ret);
        h.end_main();
        EXPECT_EQ(h.load(), "native function F has a different signature than the program expects");
    }
}

} // namespace
} // namespace eposp::vm::test
