#include "eposp/drives/motion/homing_procedure.hpp"
#include "eposp/drives/motion/statusword_bits.hpp"
#include "eposp/drives/plant/servo_axis.hpp"
#include "plant_test_motor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <gtest/gtest.h>
#include <numbers>
#include <string>

namespace eposp::drives::motion {
namespace {

constexpr std::int64_t kTurn = 2000; // the 500-pulse encoder of the test axis
constexpr std::int64_t kHomePosition = 100000;
constexpr std::int64_t kFewQuadcounts = 3;
constexpr double kPeriod = plant::ServoAxis::kOuterLoopPeriod;

::testing::AssertionResult within(std::int64_t actual, std::int64_t expected,
                                  std::int64_t tolerance) {
    if (std::llabs(actual - expected) <= tolerance) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << actual << " is not within " << tolerance << " of " << expected;
}

HomingParameters parameters(HomingMethod method, std::int64_t home_offset = 0) {
    HomingParameters p;
    p.method = method;
    p.switch_search_speed = 20000; // 600 rpm
    p.zero_search_speed = 1000;    // 30 rpm: one quadcount per control period
    p.acceleration = 200000;
    p.home_offset = home_offset;
    p.home_position = kHomePosition;
    p.current_threshold = 1.0;
    p.counts_per_turn = kTurn;
    return p;
}

/// Rigid mechanical stops in quadcounts (the current threshold methods push against them).
struct EndStops {
    std::optional<std::int64_t> negative;
    std::optional<std::int64_t> positive;
};

struct RigOptions {
    plant::SwitchLayout switches;
    std::int64_t start = 0;
    EndStops stops;
    bool encoder_has_index = true;
    bool limit_inputs_swapped = false; ///< miswired digital inputs (0x2070)
};

RigOptions rig_with(const plant::SwitchLayout& switches, std::int64_t start = 0,
                    EndStops stops = {}) {
    return {switches, start, stops, true, false};
}

/// The homing procedure closing the loop around the servo axis of the plant, the way the drive
/// will: every 1 ms control period it senses switches, the latched index, the current and the
/// position, and sets the position demand; the position offset of a completed homing shifts the
/// drive's position counter (the plant keeps its raw count).
class HomingRig {
public:
    explicit HomingRig(const RigOptions& options) : options_(options), axis_(axis_parameters()) {
        // Mid-count, so that quantisation reads `start`; one unpowered step takes the reading.
        axis_.motor().set_state({0, 0, angle_of(static_cast<double>(options.start) + 0.5)});
        axis_.step();
        axis_.set_mode(plant::ControlMode::Position);
        axis_.set_demand({static_cast<double>(options.start), 0, 0, 0});
    }

    void start(const HomingParameters& p) {
        homing_.reset(static_cast<double>(position()));
        homing_.start(now_, p, {static_cast<double>(position()), 0, 0});
    }

    void run_period() {
        const HomingStep step = homing_.update(now_, sense());
        demand_ = step.demand;
        if (step.position_offset) {
            offset_ += *step.position_offset;
        }
        const double raw_demand = step.demand.position - static_cast<double>(offset_);
        axis_.set_demand({raw_demand, step.demand.velocity, step.demand.acceleration, 0});
        latched_index_.reset();
        for (int i = 0; i < plant::ServoAxis::kCurrentStepsPerOuterLoop; ++i) {
            axis_.step();
            hold_at_end_stops();
            if (axis_.index_passed() && options_.encoder_has_index) {
                latched_index_ = axis_.position_actual();
            }
        }
        now_ += kPeriod;
    }

    /// Runs until `done` holds (checked every period) or the time runs out; false then.
    bool run_until(const std::function<bool()>& done, double max_seconds = 20) {
        const double end = now_ + max_seconds;
        while (now_ < end) {
            run_period();
            if (done()) {
                return true;
            }
        }
        return false;
    }

    bool run_until_settled() {
        const bool finished = run_until([&] {
            const std::uint16_t bits = homing_.statusword_bits(now_);
            return (bits & kTargetReachedBit) != 0 && !homing_.in_progress();
        });
        run_for(3.0); // the position loop's integrator overcomes the Coulomb friction
        return finished;
    }

    void run_for(double seconds) {
        run_until([] { return false; }, seconds);
    }

    HomingProcedure& homing() { return homing_; }
    const MotionState& demand() const { return demand_; }
    double now() const { return now_; }
    std::int64_t raw_position() const { return axis_.position_actual(); }
    std::int64_t position() const { return axis_.position_actual() + offset_; }
    std::uint16_t bits() const { return homing_.statusword_bits(now_); }

private:
    static plant::AxisParameters axis_parameters() {
        plant::AxisParameters axis = plant::test::tuned_axis();
        axis.switches = {};
        return axis;
    }

    static double angle_of(double counts) {
        return counts * 2 * std::numbers::pi / static_cast<double>(kTurn);
    }

    HomingInputs sense() const {
        const plant::SwitchStates switches =
            plant::switch_states(options_.switches, axis_.position_actual());
        HomingInputs sensed;
        sensed.position = position();
        sensed.negative_limit =
            options_.limit_inputs_swapped ? switches.positive_limit : switches.negative_limit;
        sensed.positive_limit =
            options_.limit_inputs_swapped ? switches.negative_limit : switches.positive_limit;
        sensed.home_switch = switches.home;
        if (latched_index_) {
            sensed.index_position = *latched_index_ + offset_;
        }
        sensed.current = axis_.current_actual();
        return sensed;
    }

    // A rigid stop: the shaft goes no further and stops dead there.
    void hold_at_end_stops() {
        const plant::MotorState state = axis_.motor().state();
        const auto hold = [&](std::int64_t stop) {
            axis_.motor().set_state({state.current, 0, angle_of(static_cast<double>(stop) + 0.5)});
        };
        if (options_.stops.positive && axis_.position_actual() > *options_.stops.positive) {
            hold(*options_.stops.positive);
        } else if (options_.stops.negative && axis_.position_actual() < *options_.stops.negative) {
            hold(*options_.stops.negative);
        }
    }

    RigOptions options_;
    plant::ServoAxis axis_;
    HomingProcedure homing_;
    double now_ = 0;
    std::int64_t offset_ = 0;
    std::optional<std::int64_t> latched_index_;
    MotionState demand_;
};

plant::SwitchLayout limits(std::optional<std::int64_t> negative,
                           std::optional<std::int64_t> positive) {
    return {negative, positive, std::nullopt, true, std::nullopt};
}

/// A home cam `length` counts long with its edge at `edge`, pressed above or below it, between
/// limit switches at ±20000.
plant::SwitchLayout home_cam(std::int64_t edge, bool active_above, std::int64_t length = 1000) {
    return {-20000, 20000, edge, active_above, length};
}

struct HomingCase {
    std::string name;
    HomingMethod method;
    RigOptions rig;
    std::int64_t home_offset;
    std::int64_t expected_raw_home; ///< closed form: switch edge or index position + home offset
};

// Switch edges: a limit switch at N is active at and below N, so leaving it upwards it falls at
// N + 1. An index is latched where the count crosses a multiple of a turn.
const HomingCase kHomingCases[] = {
    {"M1_NegativeLimitSwitchAndIndex", HomingMethod::NegativeLimitSwitchIndex,
     rig_with(limits(-5300, 20000)), 300, -4000 + 300},
    {"M2_PositiveLimitSwitchAndIndex", HomingMethod::PositiveLimitSwitchIndex,
     rig_with(limits(-20000, 5300)), -300, 4000 - 300},
    {"M7_HomeSwitchPositiveAndIndex", HomingMethod::HomeSwitchPositiveIndex,
     rig_with(home_cam(3300, true)), 0, 2000},
    {"M11_HomeSwitchNegativeAndIndex", HomingMethod::HomeSwitchNegativeIndex,
     rig_with(home_cam(3300, false), 5000), 0, 4000},
    {"M17_NegativeLimitSwitch", HomingMethod::NegativeLimitSwitch, rig_with(limits(-5300, 20000)),
     500, -5299 + 500},
    {"M18_PositiveLimitSwitch", HomingMethod::PositiveLimitSwitch, rig_with(limits(-20000, 5300)),
     -500, 5299 - 500},
    {"M23_HomeSwitchPositive", HomingMethod::HomeSwitchPositive, rig_with(home_cam(3300, true)),
     250, 3299 + 250},
    {"M27_HomeSwitchNegative", HomingMethod::HomeSwitchNegative,
     rig_with(home_cam(3300, false), 5000), -250, 3300 - 250},
    {"M33_IndexNegative", HomingMethod::IndexNegative, rig_with(limits(-20000, 20000), 500), 100,
     0 + 100},
    {"M34_IndexPositive", HomingMethod::IndexPositive, rig_with(limits(-20000, 20000), 500), 100,
     2000 + 100},
    {"M35_ActualPosition", HomingMethod::ActualPosition, rig_with(limits(-20000, 20000), 1234), 0,
     1234},
    {"Mminus1_CurrentThresholdPositiveAndIndex", HomingMethod::CurrentThresholdPositiveIndex,
     rig_with(limits(-20000, 20000), 0, {std::nullopt, 6500}), -200, 6000 - 200},
    {"Mminus2_CurrentThresholdNegativeAndIndex", HomingMethod::CurrentThresholdNegativeIndex,
     rig_with(limits(-20000, 20000), 0, {-6500, std::nullopt}), 200, -6000 + 200},
    {"Mminus3_CurrentThresholdPositive", HomingMethod::CurrentThresholdPositive,
     rig_with(limits(-20000, 20000), 0, {std::nullopt, 6500}), -400, 6500 - 400},
    {"Mminus4_CurrentThresholdNegative", HomingMethod::CurrentThresholdNegative,
     rig_with(limits(-20000, 20000), 0, {-6500, std::nullopt}), 400, -6500 + 400},
    // Starting on the switch, the search leaves it at once (5.4.3.3).
    {"M7_StartingOnTheHomeSwitch", HomingMethod::HomeSwitchPositiveIndex,
     rig_with(home_cam(3300, true), 3800), 0, 2000},
    {"M1_StartingOnTheLimitSwitch", HomingMethod::NegativeLimitSwitchIndex,
     rig_with(limits(-5300, 20000), -5600), 0, -4000},
    // The home cam lies behind: turn at the positive limit switch, cross the cam (CiA 402).
    {"M7_TurningAtTheLimitSwitch", HomingMethod::HomeSwitchPositiveIndex,
     rig_with({-20000, 8000, 3300, true, 1000}, 5000), 0, 2000},
    {"M11_TurningAtTheLimitSwitch", HomingMethod::HomeSwitchNegativeIndex,
     rig_with({-8000, 20000, 3300, false, 1000}), 0, 4000},
};

class HomingMethods : public ::testing::TestWithParam<HomingCase> {};

TEST_P(HomingMethods, EndsOnTheClosedFormHomeReadingHomePosition) {
    const HomingCase& c = GetParam();
    HomingRig rig(c.rig);
    rig.start(parameters(c.method, c.home_offset));
    ASSERT_TRUE(rig.run_until_settled());
    EXPECT_TRUE(within(rig.raw_position(), c.expected_raw_home, kFewQuadcounts));
    EXPECT_TRUE(within(rig.position(), kHomePosition, kFewQuadcounts));
    EXPECT_EQ(rig.bits(), kTargetReachedBit | kHomingAttainedBit);
    EXPECT_TRUE(rig.homing().referenced());
    EXPECT_FALSE(rig.homing().failure());
}

INSTANTIATE_TEST_SUITE_P(Table8_121, HomingMethods, ::testing::ValuesIn(kHomingCases),
                         [](const auto& row) { return row.param.name; });

TEST(Homing, SinSquaredRampsReachTheSameHome) {
    HomingRig rig(rig_with(home_cam(3300, true)));
    HomingParameters p = parameters(HomingMethod::HomeSwitchPositiveIndex);
    p.shape = RampShape::SinSquared;
    rig.start(p);
    ASSERT_TRUE(rig.run_until_settled());
    EXPECT_TRUE(within(rig.raw_position(), 2000, kFewQuadcounts));
}

TEST(Homing, DemandRampsWithTheHomingAccelerationUpToTheSearchSpeed) {
    // Search, turn at the limit switch, cross the cam, index, home offset: every kind of move.
    HomingRig rig(rig_with({-20000, 8000, 3300, true, 1000}, 5000));
    const HomingParameters p = parameters(HomingMethod::HomeSwitchPositiveIndex, 700);
    rig.start(p);
    MotionState previous{5000, 0, 0}; // at rest where it starts
    double peak_speed = 0;
    bool reached_search_speed = false;
    while (rig.homing().in_progress()) {
        rig.run_period();
        ASSERT_LT(rig.now(), 20);
        const MotionState now = rig.demand();
        if (rig.homing().in_progress()) { // the completing period re-zeroes the position
            ASSERT_LE(std::abs(now.velocity - previous.velocity), p.acceleration * kPeriod * 1.001);
            ASSERT_LE(std::abs(now.position - previous.position),
                      std::max(std::abs(now.velocity), std::abs(previous.velocity)) * kPeriod +
                          1e-6);
        }
        peak_speed = std::max(peak_speed, std::abs(now.velocity));
        reached_search_speed = reached_search_speed || peak_speed == p.switch_search_speed;
        previous = now;
    }
    EXPECT_TRUE(reached_search_speed);
    EXPECT_LE(peak_speed, p.switch_search_speed);
}

TEST(Homing, ProgressReadsNoModeBits) {
    HomingRig rig(rig_with(home_cam(3300, true)));
    EXPECT_EQ(rig.bits(), kTargetReachedBit); // not started (CiA 402: 0 0 1)
    rig.start(parameters(HomingMethod::HomeSwitchPositiveIndex));
    rig.run_for(0.05);
    EXPECT_EQ(rig.bits(), 0);
    EXPECT_TRUE(rig.homing().in_progress());
    EXPECT_FALSE(rig.homing().referenced());
}

struct FailureCase {
    std::string name;
    HomingMethod method;
    RigOptions rig;
    HomingFailure failure;
    std::optional<std::uint16_t> error_code;
};

const FailureCase kFailureCases[] = {
    // No home switch: turned at one limit switch, the search meets the other.
    {"HomeSwitchNeverFound", HomingMethod::HomeSwitchPositiveIndex, rig_with(limits(-6000, 6000)),
     HomingFailure::NegativeLimitSwitch, 0xFF06},
    // The negative limit switch wired to the positive input: the wrong switch trips.
    {"WrongLimitSwitch",
     HomingMethod::NegativeLimitSwitch,
     {limits(-5300, 20000), 0, {}, true, /*limit_inputs_swapped=*/true},
     HomingFailure::PositiveLimitSwitch,
     0xFF07},
    {"LimitSwitchInsteadOfEndStop", HomingMethod::CurrentThresholdPositive,
     rig_with(limits(-20000, 6000)), HomingFailure::PositiveLimitSwitch, 0xFF07},
    {"LimitSwitchDuringIndexSearch", HomingMethod::IndexPositive,
     rig_with(limits(-20000, 1000), 500), HomingFailure::PositiveLimitSwitch, 0xFF07},
    {"IndexNeverFound",
     HomingMethod::IndexPositive,
     {limits(-20000, 20000), 0, {}, /*encoder_has_index=*/false, false},
     HomingFailure::IndexNotFound,
     std::nullopt},
};

class HomingFailures : public ::testing::TestWithParam<FailureCase> {};

TEST_P(HomingFailures, SetTheHomingErrorBitAndStop) {
    const FailureCase& c = GetParam();
    HomingRig rig(c.rig);
    rig.start(parameters(c.method));
    ASSERT_TRUE(rig.run_until_settled());
    ASSERT_TRUE(rig.homing().failure());
    EXPECT_EQ(*rig.homing().failure(), c.failure);
    EXPECT_EQ(error_code(c.failure), c.error_code);
    EXPECT_EQ(rig.bits(), kHomingErrorBit | kTargetReachedBit); // error, velocity 0
    EXPECT_FALSE(rig.homing().referenced());
}

INSTANTIATE_TEST_SUITE_P(Homing, HomingFailures, ::testing::ValuesIn(kFailureCases),
                         [](const auto& row) { return row.param.name; });

TEST(Homing, ErrorBitWhileStillDecelerating) {
    HomingRig rig(rig_with(limits(-20000, 6000)));
    rig.start(parameters(HomingMethod::CurrentThresholdPositive));
    ASSERT_TRUE(rig.run_until([&] { return rig.homing().failure().has_value(); }));
    EXPECT_EQ(rig.bits(), kHomingErrorBit); // CiA 402: error, velocity not 0
}

TEST(Homing, ParametersThatCannotMoveFailAtOnce) {
    const std::function<void(HomingParameters&)> mutations[] = {
        [](HomingParameters& p) { p.switch_search_speed = 0; },
        [](HomingParameters& p) { p.zero_search_speed = 0; },
        [](HomingParameters& p) { p.acceleration = 0; },
        [](HomingParameters& p) {
            p.method = HomingMethod::CurrentThresholdNegative;
            p.current_threshold = 0;
        },
    };
    for (const auto& mutate : mutations) {
        HomingRig rig(rig_with(home_cam(3300, true)));
        HomingParameters p = parameters(HomingMethod::HomeSwitchPositiveIndex);
        mutate(p);
        rig.start(p);
        rig.run_period();
        EXPECT_EQ(rig.homing().failure(), HomingFailure::InvalidParameters);
        EXPECT_EQ(rig.bits(), kHomingErrorBit | kTargetReachedBit);
        EXPECT_EQ(rig.raw_position(), 0);
    }
}

TEST(Homing, HaltStopsAndReleaseStartsOver) {
    HomingRig rig(rig_with(home_cam(3300, true)));
    rig.start(parameters(HomingMethod::HomeSwitchPositiveIndex));
    rig.run_for(0.1);
    rig.homing().set_halt(rig.now(), true);
    ASSERT_TRUE(rig.run_until([&] { return (rig.bits() & kTargetReachedBit) != 0; }, 1));
    EXPECT_EQ(rig.bits(), kTargetReachedBit); // halted: the axle stands, nothing attained
    rig.homing().set_halt(rig.now(), false);
    ASSERT_TRUE(rig.run_until_settled());
    EXPECT_TRUE(within(rig.raw_position(), 2000, kFewQuadcounts));
    EXPECT_EQ(rig.bits(), kTargetReachedBit | kHomingAttainedBit);
}

TEST(Homing, ClearingTheStartBitInterrupts) {
    HomingRig rig(rig_with(home_cam(3300, true)));
    rig.start(parameters(HomingMethod::HomeSwitchPositiveIndex));
    rig.run_for(0.1);
    rig.homing().interrupt(rig.now());
    ASSERT_TRUE(rig.run_until_settled());
    EXPECT_EQ(rig.bits(), kTargetReachedBit); // interrupted (CiA 402: 0 0 1)
    EXPECT_FALSE(rig.homing().failure());
    EXPECT_FALSE(rig.homing().referenced());
}

TEST(Homing, LosingTheDriveFunctionIsAnError) {
    HomingRig rig(rig_with(home_cam(3300, true)));
    rig.start(parameters(HomingMethod::HomeSwitchPositiveIndex));
    rig.run_for(0.1);
    rig.homing().drive_disabled(rig.now());
    EXPECT_EQ(rig.homing().failure(), HomingFailure::DriveDisabled);
    EXPECT_TRUE((rig.bits() & kHomingErrorBit) != 0);
}

TEST(Homing, ReferenceStaysUntilLost) {
    HomingRig rig(rig_with(limits(-20000, 20000), 700));
    rig.start(parameters(HomingMethod::ActualPosition));
    rig.run_period();
    EXPECT_TRUE(rig.homing().referenced());
    rig.homing().reset(static_cast<double>(rig.position())); // e.g. another mode, re-enabled
    EXPECT_TRUE(rig.homing().referenced());
    rig.homing().reference_lost();
    EXPECT_FALSE(rig.homing().referenced());
}

TEST(Homing, NoHomingRequiredAttainsWithoutMovingOrRezeroing) {
    HomingRig rig(rig_with(limits(-20000, 20000), 700));
    rig.start(parameters(HomingMethod::NoHoming));
    rig.run_period();
    rig.run_for(0.1);
    EXPECT_EQ(rig.bits(), kTargetReachedBit | kHomingAttainedBit);
    EXPECT_TRUE(within(rig.position(), 700, 1));
}

struct MethodRow {
    std::int8_t code;
    std::optional<HomingMethod> method;
};

TEST(HomingMethod, CodesOfTable8_121) {
    const MethodRow rows[] = {
        {-5, std::nullopt},
        {-4, HomingMethod::CurrentThresholdNegative},
        {-3, HomingMethod::CurrentThresholdPositive},
        {-2, HomingMethod::CurrentThresholdNegativeIndex},
        {-1, HomingMethod::CurrentThresholdPositiveIndex},
        {0, HomingMethod::NoHoming},
        {1, HomingMethod::NegativeLimitSwitchIndex},
        {2, HomingMethod::PositiveLimitSwitchIndex},
        {3, std::nullopt},
        {7, HomingMethod::HomeSwitchPositiveIndex},
        {11, HomingMethod::HomeSwitchNegativeIndex},
        {17, HomingMethod::NegativeLimitSwitch},
        {18, HomingMethod::PositiveLimitSwitch},
        {23, HomingMethod::HomeSwitchPositive},
        {27, HomingMethod::HomeSwitchNegative},
        {33, HomingMethod::IndexNegative},
        {34, HomingMethod::IndexPositive},
        {35, HomingMethod::ActualPosition},
        {36, std::nullopt},
    };
    for (const MethodRow& row : rows) {
        EXPECT_EQ(to_homing_method(row.code), row.method) << int{row.code};
    }
}

TEST(HomingMethod, MethodsWithoutIndexMirrorTheirIndexTwins) {
    const std::pair<HomingMethod, HomingMethod> twins[] = {
        {HomingMethod::NegativeLimitSwitchIndex, HomingMethod::NegativeLimitSwitch},
        {HomingMethod::PositiveLimitSwitchIndex, HomingMethod::PositiveLimitSwitch},
        {HomingMethod::HomeSwitchPositiveIndex, HomingMethod::HomeSwitchPositive},
        {HomingMethod::HomeSwitchNegativeIndex, HomingMethod::HomeSwitchNegative},
        {HomingMethod::CurrentThresholdPositiveIndex, HomingMethod::CurrentThresholdPositive},
        {HomingMethod::CurrentThresholdNegativeIndex, HomingMethod::CurrentThresholdNegative},
    };
    for (const auto& [with_index, without] : twins) {
        HomingMethodTraits expected = traits(with_index);
        EXPECT_TRUE(expected.uses_index);
        expected.uses_index = false;
        EXPECT_EQ(traits(without), expected);
    }
}

} // namespace
} // namespace eposp::drives::motion
