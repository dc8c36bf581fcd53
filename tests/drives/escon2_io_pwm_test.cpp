// The ESCON2's PWM input (ESCON2 FW spec 6.2.31, 6.2.32, 6.2.44 - 6.2.47, 7.1.30 - 7.1.35):
// frequency and duty cycle from the edges, their ranges, warnings and error, and the
// PWM-to-set-value scaling.
#include "eposp/drives/escon2/io/pwm_input.hpp"
#include "eposp/drives/escon2/io/two_point_scaling.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

using Codes = std::vector<DeviceErrorCode>;

// 50 ms of `signal` at the pin, from `from`.
double run(PwmInput& input, PwmSignal signal, double from, double seconds = 0.05) {
    signal.drive(input, from, from + seconds);
    input.update(from + seconds);
    return from + seconds;
}

// A 10 kHz, 30 % signal reads 10'000 Hz (0x314B: 100'000 in 0.1 Hz) and 30 % (0x314C: 300);
// through 0x3180 = (100, 0 rpm, 900, 4000 rpm) it sets 0 + (300 − 100) · 4000 / 800 = 1000 rpm.
TEST(Escon2Pwm, TenKilohertzThirtyPercentGivesTheScaledVelocity) {
    PwmInput input(1, 0);
    run(input, {.frequency = 10'000, .duty_cycle = 30}, 0);
    EXPECT_NEAR(input.frequency(), 10'000, 1e-6);
    EXPECT_NEAR(input.duty_cycle(), 30, 1e-6);
    EXPECT_EQ(input.frequency_object(), 100'000U);
    EXPECT_EQ(input.duty_cycle_object(), 300U);
    EXPECT_TRUE(input.conditions().empty());
    const TwoPointScaling velocity{
        .first_input = 10, .first_value = 0, .second_input = 90, .second_value = 4000};
    EXPECT_NEAR(velocity.apply(input.duty_cycle()), 1000, 1e-6);
}

// 6.2.45 - 6.2.47: the offset and current set value functions are the same line.
TEST(Escon2Pwm, CurrentAndOffsetScalingFollowTheirSlopePoints) {
    const TwoPointScaling current{
        .first_input = 10, .first_value = -2, .second_input = 90, .second_value = 2};
    EXPECT_DOUBLE_EQ(current.apply(70), 1);
    EXPECT_DOUBLE_EQ(current.apply(10), -2);
    const TwoPointScaling offset{
        .first_input = 20, .first_value = 500, .second_input = 80, .second_value = -100};
    EXPECT_DOUBLE_EQ(offset.apply(50), 200);
}

// "Invalid scaling settings (first and second duty cycle identical) results in the first
// velocity being used".
TEST(Escon2Pwm, IdenticalDutyCyclesGiveTheFirstValue) {
    const TwoPointScaling invalid{
        .first_input = 500, .first_value = 1234, .second_input = 500, .second_value = 99};
    EXPECT_EQ(invalid.apply(300), 1234);
    EXPECT_EQ(invalid.apply(500), 1234);
}

// 7.1.30: below 50 Hz the frequency warning, the frequency shown as 50 Hz; cleared in range.
TEST(Escon2Pwm, SlowFrequencyWarnsAndIsShownLimited) {
    PwmInput input(1, 0);
    run(input, {.frequency = 40, .duty_cycle = 50}, 0, 0.2);
    EXPECT_EQ(input.conditions(), Codes{DeviceErrorCode::DigitalInput1PwmFrequencyWarning});
    EXPECT_EQ(input.frequency(), 50);
    run(input, {.frequency = 1000, .duty_cycle = 50}, 0.2);
    EXPECT_TRUE(input.conditions().empty());
    EXPECT_NEAR(input.frequency(), 1000, 1e-6);
}

// 7.1.33 on input 2: above 10 kHz, shown as 10 kHz.
TEST(Escon2Pwm, FastFrequencyOnInputTwoWarnsWithItsCode) {
    PwmInput input(2, 0);
    run(input, {.frequency = 20'000, .duty_cycle = 50}, 0);
    EXPECT_EQ(input.conditions(), Codes{DeviceErrorCode::DigitalInput2PwmFrequencyWarning});
    EXPECT_EQ(input.frequency_object(), 100'000U);
}

// 6.2.32: outside 10 - 90 % the duty cycle is limited; the warning appears beyond a slight
// threshold and disappears once the duty cycle is back inside 10 - 90 %.
TEST(Escon2Pwm, DutyCycleBeyondNinetyPercentWarnsAndIsLimited) {
    PwmInput input(1, 0);
    double now = run(input, {.frequency = 1000, .duty_cycle = 90.3}, 0);
    EXPECT_TRUE(input.conditions().empty()); // within the threshold: limited, no warning
    EXPECT_EQ(input.duty_cycle(), 90);
    now = run(input, {.frequency = 1000, .duty_cycle = 95}, now);
    EXPECT_EQ(input.conditions(), Codes{DeviceErrorCode::DigitalInput1PwmDutyCycleWarning});
    EXPECT_EQ(input.duty_cycle_object(), 900U);
    now = run(input, {.frequency = 1000, .duty_cycle = 90.3}, now);
    EXPECT_TRUE(input.duty_cycle_warning()); // not yet back inside 10 - 90 %
    run(input, {.frequency = 1000, .duty_cycle = 89}, now);
    EXPECT_FALSE(input.duty_cycle_warning());
    EXPECT_NEAR(input.duty_cycle(), 89, 1e-6);
}

TEST(Escon2Pwm, DutyCycleBelowTenPercentWarnsOnInputTwo) {
    PwmInput input(2, 0);
    run(input, {.frequency = 1000, .duty_cycle = 5}, 0);
    EXPECT_EQ(input.conditions(), Codes{DeviceErrorCode::DigitalInput2PwmDutyCycleWarning});
    EXPECT_EQ(input.duty_cycle(), 10);
}

// 6.2.32: "When reaching a pulse width (positive or negative) smaller than 5 µs, error Digital
// input 1 PWM error ... is triggered"; 6.2.31: the frequency then shows 0 Hz.
TEST(Escon2Pwm, PulseShorterThanFiveMicrosecondsIsThePwmError) {
    PwmInput input(1, 0);
    double now = run(input, {.frequency = 10'000, .duty_cycle = 4}, 0); // 4 µs high
    EXPECT_EQ(input.conditions(), Codes{DeviceErrorCode::DigitalInput1PwmError});
    EXPECT_EQ(input.frequency(), 0);
    now = run(input, {.frequency = 10'000, .duty_cycle = 97}, now); // 3 µs low
    EXPECT_TRUE(input.error());
    run(input, {.frequency = 10'000, .duty_cycle = 50}, now);
    EXPECT_TRUE(input.conditions().empty());
}

// A pin held at one level is unreadable: the PWM error once no period closed for 100 ms.
TEST(Escon2Pwm, SignalThatStopsBecomesThePwmError) {
    PwmInput input(2, 0);
    const double now = run(input, {.frequency = 1000, .duty_cycle = 50}, 0);
    input.update(now + PwmInput::kUnreadableAfter - 0.002);
    EXPECT_FALSE(input.error());
    input.update(now + PwmInput::kUnreadableAfter + 0.001);
    EXPECT_EQ(input.conditions(), Codes{DeviceErrorCode::DigitalInput2PwmError});
    EXPECT_EQ(input.frequency_object(), 0U);
}

TEST(Escon2Pwm, OnlyInputsOneAndTwoMeasurePwm) {
    EXPECT_THROW(PwmInput(3, 0), std::out_of_range);
}

} // namespace
} // namespace eposp::drives::escon2
