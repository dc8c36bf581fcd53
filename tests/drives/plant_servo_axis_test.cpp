#include "eposp/drives/motion/profile_planner.hpp"
#include "eposp/drives/plant/servo_axis.hpp"
#include "plant_test_motor.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace eposp::drives::plant {
namespace {

void run_for(ServoAxis& axis, double seconds) {
    for (int i = 0; i < static_cast<int>(std::lround(seconds / ServoAxis::kCurrentLoopPeriod));
         ++i) {
        axis.step();
    }
}

TEST(ControllerGains, DictionaryUnitsConvertToSi) {
    const CurrentGains current = to_si(CurrentControlParameterSet{500, 4000});
    EXPECT_DOUBLE_EQ(current.kp, 0.5);
    EXPECT_DOUBLE_EQ(current.ki, 4000);
    const PositionGains position = to_si(PositionControlParameterSet{2000, 100, 400, 10, 250});
    EXPECT_DOUBLE_EQ(position.kp, 2.0);
    EXPECT_DOUBLE_EQ(position.ki, 0.1);
    EXPECT_DOUBLE_EQ(position.kd, 0.04);
    EXPECT_DOUBLE_EQ(position.velocity_feed_forward, 0.001);
    EXPECT_DOUBLE_EQ(position.acceleration_feed_forward, 250e-6);
}

TEST(ServoAxis, CurrentLoopStepSettlesWithinTwoMilliseconds) {
    AxisParameters parameters = test::tuned_axis();
    parameters.plant.load.coulomb_friction = 100; // locked rotor: no back-EMF
    ServoAxis axis(parameters);
    axis.set_mode(ControlMode::Current);
    axis.set_demand({.current = 1.0});
    double peak = 0;
    for (int i = 0; i < 20; ++i) {
        axis.step();
        peak = std::max(peak, axis.current_actual());
    }
    EXPECT_NEAR(axis.current_actual(), 1.0, 0.01);
    EXPECT_LT(peak, 1.02); // the PI zero cancels the L/R pole: no overshoot to speak of
}

TEST(ServoAxis, VelocityLoopHoldsTheDemandedSpeed) {
    ServoAxis axis(test::tuned_axis());
    axis.set_mode(ControlMode::Velocity);
    const double demand = 1000.0 / 60 * 2000; // 1000 rpm in quadcounts/s
    axis.set_demand({.velocity = demand});
    run_for(axis, 0.5);
    // One quadcount per millisecond is the measurement's resolution.
    EXPECT_NEAR(axis.velocity_actual(), demand, 1000);
    EXPECT_NEAR(axis.motor().state().speed * 60 / (2 * std::numbers::pi), 1000, 5);
}

TEST(ServoAxis, PositionLoopFollowsAProfileAndSettlesOnTarget) {
    ServoAxis axis(test::tuned_axis());
    axis.set_mode(ControlMode::Position);
    const motion::Trajectory move =
        motion::plan_position_move({}, 20000, {50000, 200000, 200000, motion::RampShape::Linear});
    double worst_following_error = 0;
    double t = 0;
    while (t < move.duration() + 0.3) {
        const motion::MotionState demand = move.sample(t);
        axis.set_demand({demand.position, demand.velocity, demand.acceleration, 0});
        axis.step();
        t += ServoAxis::kCurrentLoopPeriod;
        worst_following_error =
            std::max(worst_following_error,
                     std::abs(demand.position - static_cast<double>(axis.position_actual())));
    }
    EXPECT_LE(std::abs(axis.position_actual() - 20000), 1);
    EXPECT_LT(worst_following_error, 20); // feed-forward keeps it to a few quadcounts
}

TEST(ServoAxis, PowerOffLetsTheShaftCoast) {
    ServoAxis axis(test::tuned_axis());
    axis.motor().set_state({0, 100, 0});
    run_for(axis, 0.01);
    EXPECT_EQ(axis.current_actual(), 0);
    EXPECT_GT(axis.position_actual(), 0);
}

TEST(ServoAxis, EcMotorReportsHallSensorsAndIndex) {
    AxisParameters parameters = test::tuned_axis();
    parameters.plant.motor.kind = MotorKind::Ec;
    parameters.plant.motor.pole_pairs = 4;
    ServoAxis axis(parameters);
    axis.set_mode(ControlMode::Velocity);
    axis.set_demand({.velocity = 100000});
    int index_pulses = 0;
    for (int i = 0; i < 5000; ++i) {
        axis.step();
        index_pulses += axis.index_passed() ? 1 : 0;
        ASSERT_NE(axis.hall_sensors(), 0);
        ASSERT_NE(axis.hall_sensors(), 7);
    }
    EXPECT_EQ(index_pulses, axis.position_actual() / 2000);
}

// The axis tracks the revolution it is in instead of dividing at every step: its index pulses
// are those of the readings, forwards and backwards across zero.
TEST(ServoAxis, IndexPulsesWhereTheReadingsCrossARevolution) {
    ServoAxis axis(test::tuned_axis());
    axis.set_mode(ControlMode::Position);
    int pulses = 0;
    std::int64_t lowest = 0;
    for (const double target : {5000.0, -7000.0, 2500.0}) {
        axis.set_demand({.position = target});
        for (int i = 0; i < 4000; ++i) {
            const std::int64_t before = axis.position_actual();
            axis.step();
            ASSERT_EQ(axis.index_passed(), index_passed(before, axis.position_actual(), 500));
            pulses += axis.index_passed() ? 1 : 0;
            lowest = std::min(lowest, axis.position_actual());
        }
    }
    EXPECT_LT(lowest, -6000);
    EXPECT_GE(pulses, 13); // at least 2000, 4000; 4000 … -6000 back; -6000 … 2000 again
}

TEST(ServoAxis, SwitchesTripWhereTheAxisIs) {
    AxisParameters parameters = test::tuned_axis();
    parameters.switches = {-500, 4000, 1000, true, std::nullopt};
    ServoAxis axis(parameters);
    axis.set_mode(ControlMode::Position);
    axis.set_demand({.position = 1500});
    run_for(axis, 0.3);
    EXPECT_EQ(axis.switches(), (SwitchStates{false, false, true}));
    axis.set_demand({.position = -800});
    run_for(axis, 0.3);
    EXPECT_EQ(axis.switches(), (SwitchStates{true, false, false}));
}

// switches() keeps its result for the shaft's angle: a new layout at the same angle, and the
// shaft turned from outside without a step, each show at once; ±0 rad is count 0 either way.
TEST(ServoAxis, SwitchesFollowANewLayoutAndAShaftTurnedFromOutside) {
    AxisParameters parameters = test::tuned_axis();
    parameters.switches = {-500, 4000, 1000, true, std::nullopt};
    ServoAxis axis(parameters);
    EXPECT_EQ(axis.switches(), (SwitchStates{false, false, false}));
    parameters.switches.home = 0;
    axis.reconfigure(parameters);
    EXPECT_EQ(axis.switches(), (SwitchStates{false, false, true}));
    axis.motor().set_state({.angle = -0.0});
    EXPECT_EQ(axis.switches(), (SwitchStates{false, false, true}));
    // A count is 2π / 2000 rad with 500 pulses: -600 counts and 4100 counts.
    const double radians_per_count = 2 * std::numbers::pi / 2000;
    axis.motor().set_state({.angle = -600 * radians_per_count});
    EXPECT_EQ(axis.switches(), (SwitchStates{true, false, false}));
    axis.motor().set_state({.angle = 4100.5 * radians_per_count});
    EXPECT_EQ(axis.switches(), (SwitchStates{false, true, true}));
    parameters.switches.positive_limit.reset();
    axis.reconfigure(parameters);
    EXPECT_EQ(axis.switches(), (SwitchStates{false, false, true}));
}

// 8.2.74: with a gear configured the encoder is on the gear's output. A 3:1 gear: N output turns
// are N × 4 × pulses counts while the motor turns 3N times, and the index pulses once per output
// turn; the loop, reading the counts through the gear, settles as on the motor shaft.
TEST(ServoAxis, EncoderOnTheGearOutputCountsOutputTurns) {
    AxisParameters parameters = test::tuned_axis();
    parameters.plant.gearhead.ratio = 3;
    parameters.encoder_mounting.on_gear_output = true;
    parameters.encoder_reading.gear_ratio = 3;
    ServoAxis axis(parameters);
    axis.set_mode(ControlMode::Position);
    constexpr int kOutputTurns = 2;
    axis.set_demand({.position = kOutputTurns * 2000.0});
    int index_pulses = 0;
    for (int i = 0; i < 20000; ++i) {
        axis.step();
        index_pulses += axis.index_passed() ? 1 : 0;
    }
    EXPECT_LE(std::abs(axis.position_actual() - kOutputTurns * 2000), 1);
    // Within the count the reading rounds down to; a count of the output is 3 of the motor.
    const double count = 2 * std::numbers::pi / 2000;
    EXPECT_NEAR(axis.encoder_angle(), kOutputTurns * 2 * std::numbers::pi, 2 * count);
    EXPECT_NEAR(axis.motor().state().angle, 3 * kOutputTurns * 2 * std::numbers::pi, 3 * 2 * count);
    EXPECT_EQ(index_pulses, kOutputTurns);
}

// Table 8-104: an encoder mounted the other way round, read inverted, moves the axis exactly as
// the reference axis: the same counts at every step.
TEST(ServoAxis, EncoderCountingAgainstTheMotorReadsRightWhenInverted) {
    AxisParameters reversed = test::tuned_axis();
    reversed.encoder_mounting.counts_against_motor = true;
    reversed.encoder_reading.inverted = true;
    ServoAxis axis(reversed);
    ServoAxis reference(test::tuned_axis());
    for (ServoAxis* each : {&axis, &reference}) {
        each->set_mode(ControlMode::Position);
        each->set_demand({.position = 3000});
    }
    for (int i = 0; i < 10000; ++i) {
        axis.step();
        reference.step();
        ASSERT_EQ(axis.position_actual(), reference.position_actual()) << i;
    }
    EXPECT_LE(std::abs(axis.position_actual() - 3000), 20) << "settling on the demand";
    EXPECT_GT(axis.motor().state().angle, 0) << "the motor turned its positive way";
}

// The same encoder read as if it counted with the motor: the loop pushes the motor the way that
// makes the reading run away from the demand (positive feedback) until the current limit.
TEST(ServoAxis, EncoderCountingAgainstTheMotorRunsAwayWhenNotInverted) {
    AxisParameters reversed = test::tuned_axis();
    reversed.encoder_mounting.counts_against_motor = true;
    ServoAxis axis(reversed);
    axis.set_mode(ControlMode::Position);
    axis.set_demand({.position = 100});
    run_for(axis, 0.1);
    EXPECT_LT(axis.position_actual(), -10000) << "away from the demand";
    EXPECT_GT(axis.motor().state().angle, 5 * 2 * std::numbers::pi) << "the motor turned on";
    EXPECT_NEAR(axis.current_demand(), 3, 1e-9) << "at the current limit";
}

} // namespace
} // namespace eposp::drives::plant
