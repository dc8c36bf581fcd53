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

// The level is the thermal model of a winding with ambient 0 and R_th 1 under the power
// (I / I_continuous)², bit for bit: the limitation steps towards the power itself, which is that
// body's steady state. Currents of both signs and zero, a step of another length and new
// parameters (which keep the level) on the way.
TEST(I2tCurrentLimit, LevelIsTheNormalisedThermalModelBitForBit) {
    const I2tParameters first{
        .continuous_current = 1.3, .output_current_limit = 4, .time_constant = 0.7};
    const I2tParameters second{
        .continuous_current = 0.9, .output_current_limit = 3, .time_constant = 1.9};
    I2tCurrentLimit i2t(first);
    plant::ThermalModel winding(
        {.ambient_temperature = 0, .thermal_resistance = 1, .time_constant = first.time_constant});
    const auto step = [&](double current, double dt, double continuous) {
        i2t.update(current, dt);
        const double ratio = current / continuous;
        winding.step(ratio * ratio, dt);
        ASSERT_EQ(i2t.level(), winding.temperature()) << current << " A for " << dt << " s";
    };
    for (int n = 0; n < 5000; ++n) {
        step(3.7 * std::sin(n * 0.013) - 0.2, n < 2500 ? kStep : 1e-3, first.continuous_current);
    }
    step(0, kStep, first.continuous_current);
    step(-0.0, kStep, first.continuous_current);
    i2t.set_parameters(second);
    winding.set_parameters(
        {.ambient_temperature = 0, .thermal_resistance = 1, .time_constant = second.time_constant});
    for (int n = 0; n < 5000; ++n) {
        step(-2.5 * std::cos(n * 0.007), kStep, second.continuous_current);
    }
}

} // namespace
} // namespace eposp::drives::motion
