// The ESCON2's output current limitation by the I²t method (ESCON2 FW spec 3.6.2, 6.2.55,
// 6.2.56) against the manual's formulas and worked examples.
#include "eposp/drives/escon2/protection/output_current_limitation.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

constexpr double kStep = 1e-4;
constexpr double kCool = 25; ///< °C, a power stage far below its warning temperature

// 3.6.2's example motor: nominal ("current limit") 1470 mA, τ_th 2.8 s, output limit 2940 mA.
CurrentLimitationParameters example_motor() {
    return {.motor = {.continuous_current = 1.47,
                      .output_current_limit = 2.94,
                      .time_constant = 2.8,
                      .release_level = CurrentLimitationParameters::kReleaseLevel},
            .power_stage = std::nullopt,
            .max_power_stage_temperature = 110};
}

// Seconds of `current` until the limitation sets in (or `give_up`).
double time_until_limiting(OutputCurrentLimitation& limitation, double current, double give_up) {
    double t = 0;
    while (!limitation.limiting() && t < give_up) {
        limitation.update(current, kCool, kStep);
        t += kStep;
    }
    return t;
}

// 3.6.2: 2940 mA / 1470 mA = 2; figure 9 gives ≈ 0.3 normalised duration, 0.3 · 2.8 s = 840 ms.
// The curve is T_peak/τ = −ln(1 − 1/k²) = 0.2877, 805 ms.
TEST(Escon2I2t, PeakCurrentDurationOfTheManualsExample) {
    EXPECT_NEAR(motion::peak_current_duration(2940.0 / 1470.0, 2.8) / 2.8, 0.3, 0.015);
    EXPECT_NEAR(motion::peak_current_duration(2, 2.8), -2.8 * std::log(0.75), 1e-12);
    EXPECT_TRUE(std::isinf(motion::peak_current_duration(1, 2.8)));
}

TEST(Escon2I2t, TheExampleMotorIsLimitedAfterThePeakCurrentDuration) {
    OutputCurrentLimitation limitation(example_motor());
    EXPECT_EQ(limitation.limit(), 2.94);
    EXPECT_NEAR(time_until_limiting(limitation, 2.94, 5), motion::peak_current_duration(2, 2.8),
                2 * kStep);
    EXPECT_EQ(limitation.limit(), 1.47); // "reduces the output current to the nominal current"
    EXPECT_NEAR(limitation.motor_level(), 1, 1e-3);
}

// The equation τ_th = −T_peak / ln(1 − (I_N / I_peak)²) inverts the peak duration.
TEST(Escon2I2t, ThermalTimeConstantFromPeakCurrentAndDuration) {
    EXPECT_NEAR(motion::thermal_time_constant(2.94, -2.8 * std::log(0.75), 1.47), 2.8, 1e-12);
    EXPECT_THROW(motion::thermal_time_constant(1, 1, 1), std::invalid_argument);
}

// 3.6.2: "This limit is deactivated when the I2T level of the motor falls below 90 %": without
// current the level falls from 100 % to 90 % in τ·ln(1/0.9).
TEST(Escon2I2t, LimitationIsLiftedBelowNinetyPercent) {
    OutputCurrentLimitation limitation(example_motor());
    time_until_limiting(limitation, 2.94, 5);
    ASSERT_TRUE(limitation.limiting());
    const double start = limitation.motor_level();
    double t = 0;
    while (limitation.limiting() && t < 5) {
        EXPECT_GE(limitation.motor_level(), 0.9);
        limitation.update(0, kCool, kStep);
        t += kStep;
    }
    EXPECT_NEAR(t, 2.8 * std::log(start / 0.9), 2 * kStep);
    EXPECT_EQ(limitation.limit(), 2.94);
}

// Held at the nominal current the level stays at 100 %: the limitation is never lifted.
TEST(Escon2I2t, NominalCurrentKeepsTheLimitation) {
    OutputCurrentLimitation limitation(example_motor());
    time_until_limiting(limitation, 2.94, 5);
    for (int i = 0; i < 100'000; ++i) {
        limitation.update(1.47, kCool, kStep);
    }
    EXPECT_TRUE(limitation.limiting());
    EXPECT_NEAR(limitation.motor_level(), 1, 1e-3);
}

// 3.6.2, figure 10: T_total = τ_th = 2.8 s and 10 % duty cycle allow ≈ 2.6 · I_N (3822 mA);
// the curve is √((1 − e^(−T/τ)) / (1 − e^(−D·T/τ))) = 2.577.
TEST(Escon2I2t, CyclicOnCurrentOfTheManualsExample) {
    const double k = motion::max_cyclic_on_current(0.1, 2.8, 2.8);
    EXPECT_NEAR(k, 2.6, 0.05);
    EXPECT_NEAR(k, std::sqrt(-std::expm1(-1.0) / -std::expm1(-0.1)), 1e-12);
    EXPECT_THROW(motion::max_cyclic_on_current(0, 1, 1), std::invalid_argument);
}

// Run for ever at that ON current the motor is never limited; 2 % more and it is.
TEST(Escon2I2t, CyclicCurrentAtTheDutyCycleLimitNeverLimits) {
    const double k = motion::max_cyclic_on_current(0.1, 2.8, 2.8);
    const auto limited_within = [](double on_current, int cycles) {
        CurrentLimitationParameters parameters = example_motor();
        parameters.motor.output_current_limit = 10;
        OutputCurrentLimitation limitation(parameters);
        for (int cycle = 0; cycle < cycles; ++cycle) {
            for (int i = 0; i < 28'000; ++i) {
                limitation.update(i < 2'800 ? on_current : 0, kCool, kStep);
                if (limitation.limiting()) {
                    return true;
                }
            }
        }
        return false;
    };
    EXPECT_FALSE(limited_within(0.995 * k * 1.47, 30));
    EXPECT_TRUE(limited_within(1.02 * k * 1.47, 30));
}

// 6.2.56: the power stage has its own I²t; the smaller limit wins.
TEST(Escon2I2t, PowerStageI2tLimitsBelowTheMotors) {
    CurrentLimitationParameters parameters = example_motor();
    parameters.motor = {.continuous_current = 10,
                        .output_current_limit = 20,
                        .time_constant = 100,
                        .release_level = 0.9};
    parameters.power_stage = motion::I2tParameters{.continuous_current = 5,
                                                   .output_current_limit = 15,
                                                   .time_constant = 1,
                                                   .release_level = 0.9};
    OutputCurrentLimitation limitation(parameters);
    EXPECT_EQ(limitation.limit(), 15);
    EXPECT_NEAR(time_until_limiting(limitation, 10, 5), motion::peak_current_duration(2, 1),
                2 * kStep);
    EXPECT_EQ(limitation.limit(), 5);
    EXPECT_NEAR(limitation.power_stage_level(), 1, 1e-3);
    EXPECT_LT(limitation.motor_level(), 0.1);
}

// 6.2.56.2, table 95: full current up to max − 10 °C, then linearly less, none at the maximum.
TEST(Escon2I2t, PowerStageTemperatureReducesTheLimitLinearly) {
    OutputCurrentLimitation limitation(example_motor());
    limitation.update(0, 100, kStep);
    EXPECT_EQ(limitation.limit(), 2.94);
    EXPECT_FALSE(limitation.limiting());
    limitation.update(0, 105, kStep);
    EXPECT_DOUBLE_EQ(limitation.limit(), 1.47);
    EXPECT_TRUE(limitation.limiting());
    limitation.update(0, 110, kStep);
    EXPECT_EQ(limitation.limit(), 0);
    EXPECT_EQ(power_stage_temperature_derating(92.5, 100), 0.75);
}

} // namespace
} // namespace eposp::drives::escon2
