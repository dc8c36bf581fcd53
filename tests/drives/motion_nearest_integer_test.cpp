#include "eposp/drives/motion/nearest_integer.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <random>

namespace eposp::drives::motion {
namespace {

void expect_lround(double value) {
    ASSERT_EQ(nearest_integer(value), std::lround(value)) << std::hexfloat << value;
}

// Halves (ties go away from zero), their neighbours one ulp either side, the edge where doubles
// stop having fractions (2^52, 2^53), the ends of long, ±0, infinities, NaN, and random bit
// patterns over every exponent.
TEST(NearestInteger, EqualsLroundForEveryKindOfInput) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (std::int64_t k = -200'000; k <= 200'000; ++k) {
        for (const double value : {static_cast<double>(k), static_cast<double>(k) + 0.5}) {
            expect_lround(value);
            expect_lround(std::nextafter(value, kInf));
            expect_lround(std::nextafter(value, -kInf));
        }
    }
    for (int exponent = 40; exponent <= 64; ++exponent) {
        const double power = std::ldexp(1.0, exponent);
        for (const double value : {power, power - 0.5, power + 0.5, power - 1.5}) {
            for (const double signed_value : {value, -value}) {
                expect_lround(signed_value);
                expect_lround(std::nextafter(signed_value, kInf));
                expect_lround(std::nextafter(signed_value, -kInf));
            }
        }
    }
    for (const double value :
         {0.0, -0.0, 0.49999999999999994, -0.49999999999999994,
          std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
          kInf, -kInf, std::numeric_limits<double>::quiet_NaN()}) {
        expect_lround(value);
    }
    std::mt19937_64 random(19);
    for (int i = 0; i < 1'000'000; ++i) {
        expect_lround(std::bit_cast<double>(random()));
        // Values of the size a drive rounds (counts, mA): 2^-10 ... 2^40.
        expect_lround(std::ldexp(std::uniform_real_distribution<double>(-1, 1)(random),
                                 std::uniform_int_distribution<int>(-10, 40)(random)));
    }
}

} // namespace
} // namespace eposp::drives::motion
