// When the code generator's value cache forgets what it computed: writes to what a value was
// computed from, to the temporary holding it, calls, stores through pointers, releases.
#include "codegen/value_cache.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::codegen {
namespace {

using vm::Opcode;
using vm::Operand;

constexpr ValueCache::Key kKey{ValueCache::Kind::Convert, 1, 2, 3};

class ValueCacheTest : public testing::Test {
protected:
    void SetUp() override {
        // An INT at self+8 converted into the temporary frame+100.
        cache.add(kKey, Operand::local(100), 4, {{Operand::self(8), 2}});
    }
    void write(Opcode op, Operand a, Operand b = {}, Operand c = {}, std::uint16_t aux = 0) {
        cache.written(op, a, b, c, aux, [](std::uint16_t) { return 64U; });
    }
    bool remembered() const { return cache.find(kKey).has_value(); }

    ValueCache cache;
};

TEST_F(ValueCacheTest, KeepsTheValueWhileOtherMemoryChanges) {
    write(Opcode::Mov32, Operand::self(10), Operand::self(0));
    write(Opcode::Mov32, Operand::local(104), Operand::self(0));
    write(Opcode::Mov16, Operand::global(8), Operand::self(0)); // same offset, other area
    EXPECT_TRUE(remembered());
}

TEST_F(ValueCacheTest, ForgetsWhenItsSourceIsWritten) {
    write(Opcode::Mov8, Operand::self(9), Operand::self(0));
    EXPECT_FALSE(remembered());
}

TEST_F(ValueCacheTest, ForgetsWhenItsTemporaryIsWritten) {
    write(Opcode::Mov64, Operand::local(96), Operand::self(0));
    EXPECT_FALSE(remembered());
}

TEST_F(ValueCacheTest, ForgetsWhenABlockCopyOrAnArrayStoreCoversTheSource) {
    write(Opcode::MovN, Operand::self(0), Operand::global(8), Operand::imm(16));
    EXPECT_FALSE(remembered());
    SetUp();
    write(Opcode::Stx16, Operand::self(0), Operand::local(0), Operand::local(4), 0);
    EXPECT_FALSE(remembered());
}

TEST_F(ValueCacheTest, ForgetsEverythingAtCallsAndStoresThroughPointers) {
    for (const Opcode op : {Opcode::Call, Opcode::CallFb, Opcode::CallNative, Opcode::Stp32}) {
        SetUp();
        write(op, Operand::imm(0));
        EXPECT_FALSE(remembered()) << vm::opcode_info(op).name;
    }
}

TEST_F(ValueCacheTest, ForgetsValuesInReleasedTemporaries) {
    cache.release(104);
    EXPECT_TRUE(remembered());
    cache.release(100);
    EXPECT_FALSE(remembered());
}

} // namespace
} // namespace eposp::compiler::codegen
