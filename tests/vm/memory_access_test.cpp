// Block moves, checked array indexing, references and pointer access.

#include "vm_harness.hpp"

namespace eposp::vm::test {
namespace {

TEST(MemoryAccess, BlockMoveCopiesAStructOrString) {
    Harness h;
    const std::uint8_t text[] = {5, 'h', 'e', 'l', 'l', 'o'};
    const auto constant = h.builder.constant(text, 1);
    h.builder.emit(Opcode::MovN, self(0), Operand::global(constant), Operand::imm(sizeof text));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(std::memcmp(h.machine->memory().data() + h.instance, text, sizeof text), 0);
}

// a : ARRAY[-2..2] OF INT at self+16; a[i] := i * 10 for each i, then x := a[1].
TEST(MemoryAccess, IndexedStoreAndLoadHonourTheLowerBound) {
    Harness h;
    const auto a = h.builder.array({-2, 5, 2});
    constexpr std::uint32_t kI = 0, kValue = 4, kX = 8, kArray = 16;
    auto loop = h.builder.label();
    h.init<std::int32_t>(12, 2); // upper bound
    h.builder.emit(Opcode::Ldi32, self(kI), imm(-2));
    h.builder.bind(loop);
    h.builder.emit(Opcode::Ldi16, self(kValue), Operand::imm(10));
    h.builder.emit(Opcode::CvtI32I16, self(kValue + 2), self(kI));
    h.builder.emit(Opcode::Mul16, self(kValue), self(kValue), self(kValue + 2));
    h.builder.emit(Opcode::Stx16, self(kArray), self(kI), self(kValue), a);
    h.builder.emit(Opcode::AddI32, self(kI), self(kI), imm(1));
    h.builder.jump(Opcode::JLeI32, loop, self(kI), self(12));
    h.builder.emit(Opcode::Ldi32, self(kI), Operand::imm(1));
    h.builder.emit(Opcode::Ldx16, self(kX), self(kArray), self(kI), a);
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int16_t>(kArray), -20);
    EXPECT_EQ(h.get<std::int16_t>(kArray + 8), 20);
    EXPECT_EQ(h.get<std::int16_t>(kX), 10);
}

// m : ARRAY[0..2, 0..3] OF DINT: m[2, 1] := 99 through IdxA then IdxAP.
TEST(MemoryAccess, MultiDimensionalElementThroughChainedIndexing) {
    Harness h;
    const auto rows = h.builder.array({0, 3, 16});
    const auto columns = h.builder.array({0, 4, 4});
    h.init<std::int32_t>(0, 2);
    h.init<std::int32_t>(4, 1);
    h.init<std::int32_t>(8, 99);
    h.builder.emit(Opcode::IdxA, self(16), self(64), self(0), rows);
    h.builder.emit(Opcode::IdxAP, self(16), self(16), self(4), columns);
    h.builder.emit(Opcode::Stp32, self(16), self(8), Operand::imm(0));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(64 + 2 * 16 + 1 * 4), 99);
}

// p := REF(s); p^.y := p^.x + 1 with s : STRUCT x, y : LREAL END_STRUCT at self+32.
TEST(MemoryAccess, ReferencesReadAndWriteThroughFieldOffsets) {
    Harness h;
    h.init(32, 1.5);
    h.builder.emit(Opcode::Addr, self(0), self(32), Operand::imm(16));
    h.builder.emit(Opcode::Ldp64, self(8), self(0), Operand::imm(0));
    h.builder.emit(Opcode::Ldi64, self(16), Operand::imm(0), Operand::imm(0x3FF00000)); // 1.0
    h.builder.emit(Opcode::AddF64, self(8), self(8), self(16));
    h.builder.emit(Opcode::Stp64, self(0), self(8), Operand::imm(8));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_DOUBLE_EQ(h.get<double>(40), 2.5);
}

TEST(MemoryAccess, BlockCopyThroughPointers) {
    Harness h;
    h.init<std::uint64_t>(64, 0x1122334455667788);
    h.builder.emit(Opcode::Addr, self(0), self(64), Operand::imm(8));
    h.builder.emit(Opcode::LdpN, self(16), self(0), Operand::imm(8));
    h.builder.emit(Opcode::Addr, self(8), self(80), Operand::imm(8));
    h.builder.emit(Opcode::StpN, self(8), self(16), Operand::imm(8));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::uint64_t>(80), 0x1122334455667788U);
}

} // namespace
} // namespace eposp::vm::test
