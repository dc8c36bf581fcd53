// Integer, real, bit and comparison instructions, one table row per case: x and y are placed in
// Main's instance, the instruction writes its result there, the row gives the expected bits.

#include "vm_harness.hpp"

#include <cmath>
#include <limits>

namespace eposp::vm::test {
namespace {

struct OpCase {
    const char* name;
    Opcode opcode;
    std::uint64_t x;
    std::uint64_t y;
    std::uint64_t expected;
    std::uint32_t result_size;
};

void PrintTo(const OpCase& c, std::ostream* os) {
    *os << c.name;
}

constexpr std::uint32_t kX = 0;
constexpr std::uint32_t kY = 8;
constexpr std::uint32_t kResult = 16;

std::uint64_t run_op(const OpCase& c) {
    Harness h;
    h.init(kX, c.x);
    h.init(kY, c.y);
    const auto& info = opcode_info(c.opcode);
    h.builder.emit(c.opcode, self(kResult), self(kX),
                   info.c.field == Field::None ? Operand{} : self(kY));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    EXPECT_EQ(h.run(), RunState::Finished);
    std::uint64_t result = 0;
    std::memcpy(&result, h.machine->memory().data() + h.instance + kResult, c.result_size);
    return result;
}

class Arithmetic : public ::testing::TestWithParam<OpCase> {};

TEST_P(Arithmetic, GivesTheIecResult) {
    EXPECT_EQ(run_op(GetParam()), GetParam().expected) << GetParam().name;
}

constexpr auto kI32Min = std::numeric_limits<std::int32_t>::min();
constexpr auto kI64Min = std::numeric_limits<std::int64_t>::min();

INSTANTIATE_TEST_SUITE_P(
    IntegerWrapAroundPerWidth, Arithmetic,
    ::testing::Values(OpCase{"Add8_200_100", Opcode::Add8, 200, 100, 44, 1},
                      OpCase{"Add16_7FFF_1", Opcode::Add16, 0x7FFF, 1, 0x8000, 2},
                      OpCase{"Add32_max_1", Opcode::Add32, 0x7FFFFFFF, 1, bits(kI32Min), 4},
                      OpCase{"Add64_max_1", Opcode::Add64, 0x7FFFFFFFFFFFFFFF, 1, bits(kI64Min), 8},
                      OpCase{"Sub8_0_1", Opcode::Sub8, 0, 1, 0xFF, 1},
                      OpCase{"Sub32_min_1", Opcode::Sub32, bits(kI32Min), 1, 0x7FFFFFFF, 4},
                      OpCase{"Mul16_300_300", Opcode::Mul16, 300, 300, 90000 % 65536, 2},
                      OpCase{"Mul32_65536_65536", Opcode::Mul32, 65536, 65536, 0, 4},
                      OpCase{"Mul64_wraps", Opcode::Mul64, 0x100000001, 0x100000001, 0x200000001,
                             8},
                      OpCase{"Neg8_min", Opcode::Neg8, 0x80, 0, 0x80, 1},
                      OpCase{"Neg32_1", Opcode::Neg32, 1, 0, 0xFFFFFFFF, 4},
                      OpCase{"AbsI16_min_stays_min", Opcode::AbsI16, 0x8000, 0, 0x8000, 2},
                      OpCase{"AbsI32_minus5", Opcode::AbsI32, bits(-5), 0, 5, 4},
                      OpCase{"AbsU8_200", Opcode::AbsU8, 200, 0, 200, 1}));

INSTANTIATE_TEST_SUITE_P(
    DivisionAndModulo, Arithmetic,
    ::testing::Values(OpCase{"DivI32_minus7_2_truncates", Opcode::DivI32, bits(-7), 2, bits(-3), 4},
                      OpCase{"ModI32_minus7_2_follows_dividend", Opcode::ModI32, bits(-7), 2,
                             bits(-1), 4},
                      OpCase{"ModI32_7_minus2", Opcode::ModI32, 7, bits(-2), 1, 4},
                      OpCase{"DivU8_250_7", Opcode::DivU8, 250, 7, 35, 1},
                      OpCase{"DivI8_min_minus1_wraps", Opcode::DivI8, 0x80, 0xFF, 0x80, 1},
                      OpCase{"ModI16_min_minus1", Opcode::ModI16, 0x8000, 0xFFFF, 0, 2},
                      OpCase{"DivI64_min_minus1_wraps", Opcode::DivI64, bits(kI64Min),
                             bits(std::int64_t{-1}), bits(kI64Min), 8},
                      OpCase{"DivU32_big", Opcode::DivU32, 0xFFFFFFFF, 2, 0x7FFFFFFF, 4},
                      OpCase{"ModU64", Opcode::ModU64, 0xFFFFFFFFFFFFFFFF, 10, 5, 8},
                      OpCase{"DivF64_by_zero_is_inf", Opcode::DivF64, bits(1.0), bits(0.0),
                             bits(std::numeric_limits<double>::infinity()), 8}));

INSTANTIATE_TEST_SUITE_P(
    BitsAndShifts, Arithmetic,
    ::testing::Values(OpCase{"And16", Opcode::And16, 0xF0F0, 0xFF00, 0xF000, 2},
                      OpCase{"Or8", Opcode::Or8, 0x0F, 0xF0, 0xFF, 1},
                      OpCase{"Xor32", Opcode::Xor32, 0xFFFF0000, 0x0F0F0F0F, 0xF0F00F0F, 4},
                      OpCase{"Not64", Opcode::Not64, 0, 0, 0xFFFFFFFFFFFFFFFF, 8},
                      OpCase{"NotB_true", Opcode::NotB, 1, 0, 0, 1},
                      OpCase{"NotB_false", Opcode::NotB, 0, 0, 1, 1},
                      OpCase{"Shl8_drops_high_bit", Opcode::Shl8, 0x81, 1, 0x02, 1},
                      OpCase{"Shr16_is_logical", Opcode::Shr16, 0x8000, 15, 1, 2},
                      OpCase{"Shl32_by_width_is_0", Opcode::Shl32, 0xFFFFFFFF, 32, 0, 4},
                      OpCase{"Shr64_by_63", Opcode::Shr64, 0x8000000000000000, 63, 1, 8},
                      OpCase{"Rol8", Opcode::Rol8, 0x81, 1, 0x03, 1},
                      OpCase{"Ror16", Opcode::Ror16, 0x0001, 1, 0x8000, 2},
                      OpCase{"Rol32_count_mod_width", Opcode::Rol32, 0x80000000, 33, 1, 4},
                      OpCase{"Ror64_by_4", Opcode::Ror64, 0x1, 4, 0x1000000000000000, 8}));

INSTANTIATE_TEST_SUITE_P(
    Comparisons, Arithmetic,
    ::testing::Values(
        OpCase{"LtI8_signed", Opcode::LtI8, 0xFF, 1, 1, 1},
        OpCase{"LtU8_unsigned", Opcode::LtU8, 0xFF, 1, 0, 1},
        OpCase{"LeI64_equal", Opcode::LeI64, bits(kI64Min), bits(kI64Min), 1, 1},
        OpCase{"LtU32", Opcode::LtU32, 1, 0x80000000, 1, 1},
        OpCase{"Eq16", Opcode::Eq16, 0x1234, 0x1234, 1, 1},
        OpCase{"Ne32", Opcode::Ne32, 1, 2, 1, 1},
        OpCase{"EqF64_signed_zeros", Opcode::EqF64, bits(-0.0), bits(0.0), 1, 1},
        OpCase{"EqF32_nan", Opcode::EqF32, bits(std::nanf("")), bits(std::nanf("")), 0, 1},
        OpCase{"NeF64_nan", Opcode::NeF64, bits(std::nan("")), bits(1.0), 1, 1},
        OpCase{"LtF64", Opcode::LtF64, bits(-1.5), bits(1.0), 1, 1},
        OpCase{"LeF32_nan_is_false", Opcode::LeF32, bits(std::nanf("")), bits(1.0F), 0, 1}));

INSTANTIATE_TEST_SUITE_P(
    Reals, Arithmetic,
    ::testing::Values(OpCase{"AddF64", Opcode::AddF64, bits(0.5), bits(0.25), bits(0.75), 8},
                      OpCase{"SubF32", Opcode::SubF32, bits(1.0F), bits(2.5F), bits(-1.5F), 4},
                      OpCase{"MulF64", Opcode::MulF64, bits(1.5), bits(-4.0), bits(-6.0), 8},
                      OpCase{"DivF32", Opcode::DivF32, bits(1.0F), bits(4.0F), bits(0.25F), 4},
                      OpCase{"NegF64", Opcode::NegF64, bits(2.0), 0, bits(-2.0), 8},
                      OpCase{"AbsF32", Opcode::AbsF32, bits(-3.5F), 0, bits(3.5F), 4},
                      OpCase{"SqrtF64", Opcode::SqrtF64, bits(2.25), 0, bits(1.5), 8}));

TEST(Arithmetic, AddImmediateIsSignExtendedAndWraps) {
    Harness h;
    h.init<std::int16_t>(0, 5);
    h.init<std::uint8_t>(8, 250);
    h.builder.emit(Opcode::AddI16, self(0), self(0), imm(-7));
    h.builder.emit(Opcode::AddI8, self(8), self(8), imm(10));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int16_t>(0), -2);
    EXPECT_EQ(h.get<std::uint8_t>(8), 4);
}

TEST(Arithmetic, LoadImmediateTruncatesToWidthAndJoinsHalvesFor64Bits) {
    Harness h;
    h.builder.emit(Opcode::Ldi8, self(0), Operand::imm(0x1FF));
    h.builder.emit(Opcode::Ldi64, self(8), Operand::imm(0x89ABCDEF), Operand::imm(0x01234567));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::uint8_t>(0), 0xFF);
    EXPECT_EQ(h.get<std::uint64_t>(8), 0x0123456789ABCDEFULL);
}

} // namespace
} // namespace eposp::vm::test
