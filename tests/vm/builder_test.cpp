#include "vm_harness.hpp"

namespace eposp::vm::test {
namespace {

TEST(Builder, RefusesAnUnboundLabel) {
    Builder b;
    b.begin_body(b.declare_pou("Main", PouKind::Program, 8));
    b.jump(Opcode::Jmp, b.label());
    b.end_body(0);
    const auto image = b.finish();
    ASSERT_FALSE(image);
    EXPECT_EQ(image.error(), "label 0 used but never bound");
}

TEST(Builder, RefusesADeclaredPouWithoutBody) {
    Builder b;
    b.declare_pou("Helper", PouKind::Function);
    const auto image = b.finish();
    ASSERT_FALSE(image);
    EXPECT_EQ(image.error(), "POU Helper declared but has no body");
}

TEST(Builder, AlignsDataAndSharesEqualArrayDescriptors) {
    Builder b;
    const auto byte = b.allocate(1, 1);
    const auto lreal = b.constant(2.5);
    EXPECT_EQ(byte, kNullGuardSize) << "nothing is allocated in the NULL guard";
    EXPECT_EQ(lreal % 8, 0U);
    EXPECT_EQ(b.array({1, 10, 4}), b.array({1, 10, 4}));
    EXPECT_NE(b.array({1, 10, 4}), b.array({0, 10, 4}));
}

TEST(Builder, LineTableKeepsOneEntryPerChangeOfLine) {
    Builder b;
    const auto main = b.declare_pou("Main", PouKind::Program, 8);
    b.begin_body(main);
    b.line(1);
    b.emit(Opcode::Nop);
    b.line(1);
    b.emit(Opcode::Nop);
    b.line(2);
    b.line(3); // no instruction for line 2: line 3 starts here
    b.emit(Opcode::Ret);
    b.end_body(0);
    const auto image = b.finish();
    ASSERT_TRUE(image);
    EXPECT_EQ(image->pous[main].lines, (std::vector<LineEntry>{{0, 1}, {2, 3}}));
}

TEST(Machine, ColdStartRestoresInitialValues) {
    Harness h;
    h.init<std::int32_t>(0, 42);
    h.builder.emit(Opcode::AddI32, self(0), self(0), imm(1));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    ASSERT_EQ(h.machine->run_cycle(0), RunState::Finished);
    EXPECT_EQ(h.get<std::int32_t>(0), 44);
    h.machine->cold_start();
    EXPECT_EQ(h.get<std::int32_t>(0), 42);
}

} // namespace
} // namespace eposp::vm::test
