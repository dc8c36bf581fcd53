// The I²t output current limitation (EPOS2 FW spec 5.14.1, figure 5-40) against its closed form.
#include "eposp/drives/motion/i2t_current_limit.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace eposp::drives::motion {
namespace {

constexpr double kStep = 1e-4;

// 5.14.1's example: continuous 1.47 A, output limit 2.94 A, τ = 2.8 s; twice the continuous
// current is allowed for −τ·ln(1 − 1/4) = 0.805 s ("0.3 · 2.8 s = 840 ms" read off figure 5-40).
TEST(I2tCurrentLimit, TwiceTheContinuousCurrentIsAllowedForTheFigure5_40Time) {
    I2tCurrentLimit i2t(
        {.continuous_current = 1.47, .output_current_limit = 2.94, .time_constant = 2.8});
    double t = 0;
    while (!i2t.limiting() && t < 5) {
        EXPECT_EQ(i2t.limit(), 2.94);
        i2t.update(2.94, kStep);
        t += kStep;
    }
    EXPECT_NEAR(t, -2.8 * std::log(0.75), 2 * kStep);
    EXPECT_EQ(i2t.limit(), 1.47);
}

// The continuous current itself never limits; held at it, a limitation stays; a current below it
// releases the limitation as soon as the winding has cooled below its limit.
TEST(I2tCurrentLimit, ContinuousCurrentNeverLimitsAndALowerCurrentReleases) {
    I2tCurrentLimit i2t({.continuous_current = 1, .output_current_limit = 3, .time_constant = 1});
    for (int step = 0; step < 100'000; ++step) {
        i2t.update(0.999, kStep);
    }
    EXPECT_FALSE(i2t.limiting());
    for (int step = 0; step < 100'000 && !i2t.limiting(); ++step) {
        i2t.update(3, kStep);
    }
    ASSERT_TRUE(i2t.limiting());
    i2t.update(1, kStep); // held at the continuous current: still limited
    EXPECT_TRUE(i2t.limiting());
    for (int step = 0; step < 100; ++step) { // the winding cools below its limit within 10 ms
        i2t.update(0.5, kStep);
    }
    EXPECT_FALSE(i2t.limiting());
    EXPECT_EQ(i2t.limit(), 3);
}

} // namespace
} // namespace eposp::drives::motion
