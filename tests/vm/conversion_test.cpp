// IEC 61131-3 type conversions (*_TO_*, TRUNC): one row per rule that matters.

#include "vm_harness.hpp"

#include <cmath>
#include <limits>

namespace eposp::vm::test {
namespace {

struct ConversionCase {
    const char* name;
    Opcode opcode;
    std::uint64_t source;
    std::uint64_t expected;
    std::uint32_t result_size;
};

void PrintTo(const ConversionCase& c, std::ostream* os) {
    *os << c.name;
}

class Conversion : public ::testing::TestWithParam<ConversionCase> {};

TEST_P(Conversion, FollowsIecRules) {
    const auto& c = GetParam();
    Harness h;
    h.init(0, c.source);
    h.init<std::uint64_t>(8, 0xAAAAAAAAAAAAAAAA); // the bytes past the result must stay
    h.builder.emit(c.opcode, self(8), self(0));
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    std::uint64_t expected = 0xAAAAAAAAAAAAAAAA;
    std::memcpy(&expected, &c.expected, c.result_size);
    EXPECT_EQ(h.get<std::uint64_t>(8), expected);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

INSTANTIATE_TEST_SUITE_P(
    RealToIntegerRoundsTiesToEven, Conversion,
    ::testing::Values(
        ConversionCase{"REAL_TO_INT_2_5", Opcode::CvtF32I16, bits(2.5F), 2, 2},
        ConversionCase{"REAL_TO_INT_minus2_5", Opcode::CvtF32I16, bits(-2.5F),
                       bits(std::int16_t{-2}), 2},
        ConversionCase{"REAL_TO_INT_1_4", Opcode::CvtF32I16, bits(1.4F), 1, 2},
        ConversionCase{"LREAL_TO_DINT_minus1_6", Opcode::CvtF64I32, bits(-1.6), bits(-2), 4},
        ConversionCase{"LREAL_TO_DINT_0_5", Opcode::CvtF64I32, bits(0.5), 0, 4},
        ConversionCase{"LREAL_TO_DINT_3_5", Opcode::CvtF64I32, bits(3.5), 4, 4},
        ConversionCase{"LREAL_TO_SINT_saturates_high", Opcode::CvtF64I8, bits(300.0), 127, 1},
        ConversionCase{"LREAL_TO_SINT_saturates_low", Opcode::CvtF64I8, bits(-300.0), 0x80, 1},
        ConversionCase{"LREAL_TO_UINT_negative_is_0", Opcode::CvtF64U16, bits(-5.0), 0, 2},
        ConversionCase{"LREAL_TO_DINT_nan_is_0", Opcode::CvtF64I32, bits(kNaN), 0, 4},
        ConversionCase{"LREAL_TO_ULINT_saturates", Opcode::CvtF64U64, bits(1e20),
                       0xFFFFFFFFFFFFFFFF, 8},
        ConversionCase{"LREAL_TO_LINT_saturates", Opcode::CvtF64I64, bits(1e19), 0x7FFFFFFFFFFFFFFF,
                       8},
        ConversionCase{"TRUNC_minus2_7", Opcode::TruncF64, bits(-2.7), bits(std::int64_t{-2}), 8},
        ConversionCase{"TRUNC_REAL_2_9", Opcode::TruncF32, bits(2.9F), 2, 8}));

INSTANTIATE_TEST_SUITE_P(
    IntegersWrapOrExtend, Conversion,
    ::testing::Values(ConversionCase{"DINT_TO_SINT_wraps", Opcode::CvtI32I8, 300, 44, 1},
                      ConversionCase{"SINT_TO_DINT_sign_extends", Opcode::CvtI8I32, 0xFF,
                                     0xFFFFFFFF, 4},
                      ConversionCase{"USINT_TO_DINT_zero_extends", Opcode::CvtU8I32, 0xFF, 255, 4},
                      ConversionCase{"INT_TO_ULINT_sign_extends", Opcode::CvtI16U64, 0xFFFE,
                                     0xFFFFFFFFFFFFFFFE, 8},
                      ConversionCase{"UDINT_TO_LINT", Opcode::CvtU32I64, 0xFFFFFFFF, 0xFFFFFFFF, 8},
                      ConversionCase{"DINT_TO_DINT_copies", Opcode::CvtI32I32, 1234, 1234, 4}));

INSTANTIATE_TEST_SUITE_P(
    BoolAndReals, Conversion,
    ::testing::Values(ConversionCase{"DINT_TO_BOOL_nonzero", Opcode::CvtI32Bool, 256, 1, 1},
                      ConversionCase{"DINT_TO_BOOL_zero", Opcode::CvtI32Bool, 0, 0, 1},
                      ConversionCase{"USINT_TO_BOOL_high_bit", Opcode::CvtU8Bool, 0x80, 1, 1},
                      ConversionCase{"LREAL_TO_BOOL_half", Opcode::CvtF64Bool, bits(0.5), 1, 1},
                      ConversionCase{"BOOL_TO_INT", Opcode::CvtBoolI16, 1, 1, 2},
                      ConversionCase{"BOOL_TO_LREAL", Opcode::CvtBoolF64, 1, bits(1.0), 8},
                      ConversionCase{"DINT_TO_LREAL", Opcode::CvtI32F64, bits(-7), bits(-7.0), 8},
                      ConversionCase{"ULINT_TO_REAL", Opcode::CvtU64F32, 1ULL << 40,
                                     bits(static_cast<float>(1ULL << 40)), 4},
                      ConversionCase{"LREAL_TO_REAL", Opcode::CvtF64F32, bits(0.1), bits(0.1F), 4},
                      ConversionCase{"REAL_TO_LREAL", Opcode::CvtF32F64, bits(0.5F), bits(0.5),
                                     8}));

} // namespace
} // namespace eposp::vm::test
