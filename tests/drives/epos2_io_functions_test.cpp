// The EPOS2's digital inputs and outputs, position marker, position compare and holding brake
// as pure functions of their configuration (EPOS2 FW spec 8.2.56 - 8.2.61, 8.2.72), each against
// the tables of the specification. The drive on the bus: epos2_drive_io_test.cpp.
#include "eposp/drives/epos2/digital_inputs.hpp"
#include "eposp/drives/epos2/digital_outputs.hpp"
#include "eposp/drives/epos2/holding_brake.hpp"
#include "eposp/drives/epos2/position_compare.hpp"
#include "eposp/drives/epos2/position_marker.hpp"

#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace eposp::drives::epos2 {
namespace {

constexpr plant::SwitchStates kNoSwitch{};
constexpr std::uint16_t kNegativeLimit = 1U << 0; // table 8-87
constexpr std::uint16_t kPositiveLimit = 1U << 1;
constexpr std::uint16_t kHome = 1U << 2;
constexpr std::uint16_t kQuickStop = 1U << 5;

// Table 8-85 (24/5): the machine's switches are wired to inputs 4, 5, 6, which carry the home
// switch, positive and negative limit switch by default.
TEST(DigitalInputs, MachineSwitchesDriveInputs4To6AndTheirDefaultFunctionalities) {
    DigitalInputs inputs;
    const struct {
        plant::SwitchStates pressed;
        std::uint8_t pins;
        std::uint16_t states;
    } rows[] = {
        {{.negative_limit = true}, 0b100000, kNegativeLimit},
        {{.positive_limit = true}, 0b010000, kPositiveLimit},
        {{.home = true}, 0b001000, kHome},
        {kNoSwitch, 0, 0},
    };
    for (const auto& row : rows) {
        EXPECT_EQ(inputs.levels(row.pressed), row.pins);
        EXPECT_EQ(inputs.states(row.pressed), row.states);
    }
}

// 8.2.56: 0x2070 decides which functionality a pin carries.
TEST(DigitalInputs, ConfigurationAssignsEachPinItsFunctionality) {
    DigitalInputs inputs;
    DigitalInputConfiguration config;
    config.functions[0] = 5; // input 1: quickstop
    inputs.configure(config);
    inputs.set_level(1, true);
    EXPECT_EQ(inputs.states(kNoSwitch), kQuickStop);
    config.functions[0] = 15; // general purpose A
    inputs.configure(config);
    EXPECT_EQ(inputs.states(kNoSwitch), 1U << 15);
    inputs.set_level(1, false);
    EXPECT_EQ(inputs.states(kNoSwitch), 0);
}

// Table 8-88: polarity 1 is low active; a functionality no pin carries stays inactive.
TEST(DigitalInputs, LowActivePolarityMakesTheLowPinActive) {
    DigitalInputs inputs;
    DigitalInputConfiguration config;
    config.polarity = kHome | kQuickStop;
    inputs.configure(config);
    EXPECT_EQ(inputs.states(kNoSwitch), kHome) << "released home switch active, no quickstop pin";
    EXPECT_EQ(inputs.states({.home = true}), 0);
}

// 8.2.57: the mask filters the display (sub 1), not the states the execution sees.
TEST(DigitalInputs, MaskFiltersOnlyTheDisplayedState) {
    DigitalInputs inputs;
    DigitalInputConfiguration config;
    config.mask = kNegativeLimit;
    inputs.configure(config);
    const plant::SwitchStates both{.negative_limit = true, .positive_limit = true};
    EXPECT_EQ(inputs.states(both), kNegativeLimit | kPositiveLimit);
    EXPECT_EQ(inputs.displayed(both), kNegativeLimit);
}

// The states are a table over the 64 pin levels made when configured: every level of every
// configuration (pins carrying one functionality, two pins sharing one, low-active bits of
// functionalities no pin carries) against table 8-88's rule, also after reconfiguring.
TEST(DigitalInputs, EveryPinLevelGivesTheStatesOfItsConfiguration) {
    DigitalInputs inputs;
    std::vector<DigitalInputConfiguration> configs(4);
    configs[1].functions = {5, 4, 3, 2, 1, 0};
    configs[1].polarity = kHome | kQuickStop | (1U << 9);
    configs[2].functions = {2, 2, 15, 6, 0, 1};
    configs[2].polarity = 0xFFFF;
    configs[3].functions = {0, 15, 14, 13, 12, 11};
    configs[3].polarity = kNegativeLimit | (1U << 12);
    for (const DigitalInputConfiguration& config : configs) {
        inputs.configure(config);
        for (unsigned pins = 0; pins < 64; ++pins) {
            std::uint16_t expected = 0;
            for (unsigned n = 1; n <= kDigitalInputCount; ++n) {
                const bool high = (pins >> (n - 1) & 1U) != 0;
                inputs.set_level(n, high);
                const auto bit = static_cast<std::uint16_t>(1U << config.functions[n - 1]);
                if (high != ((config.polarity & bit) != 0)) {
                    expected |= bit;
                }
            }
            EXPECT_EQ(inputs.states(kNoSwitch), expected) << "pins " << pins;
        }
    }
}

TEST(DigitalInputs, HeldLimitSwitchDrivesItsPinAndOutsideSourcesAddUp) {
    DigitalInputs inputs;
    inputs.hold_limit_switch(InputFunction::PositiveLimitSwitch, true);
    inputs.set_level(2, true);
    EXPECT_EQ(inputs.levels(kNoSwitch), 0b010010);
    inputs.hold_limit_switch(InputFunction::PositiveLimitSwitch, false);
    EXPECT_EQ(inputs.levels(kNoSwitch), 0b000010);
}

TEST(DigitalInputs, InputBeyondTheSixOfThe24_5IsRefused) {
    DigitalInputs inputs;
    EXPECT_THROW(inputs.set_level(0, true), std::invalid_argument);
    EXPECT_THROW(inputs.set_level(7, true), std::invalid_argument);
}

// 8.2.59: a pin follows its functionality where the mask has its bit, inverted by the polarity;
// outside the mask it keeps its level.
TEST(DigitalOutputs, PinFollowsItsFunctionalityUnderMaskAndPolarity) {
    DigitalOutputs outputs;
    DigitalOutputConfiguration config;
    config.functions = {0, 1, 2, 15}; // ready/fault, compare, brake, general purpose A
    config.mask = 0x8007;
    config.polarity = 0x0004; // brake low active (8.2.72)
    outputs.configure(config);
    outputs.update(0x8001);
    EXPECT_EQ(outputs.levels(), 0b1101) << "ready high, compare low, brake inverted high, A high";
    outputs.update(0x0006);
    EXPECT_EQ(outputs.levels(), 0b0010);

    config.mask = 0x0001; // A keeps its level from here on
    outputs.configure(config);
    outputs.update(0x8001);
    EXPECT_EQ(outputs.levels(), 0b0011);
}

// The same states under a new configuration drive the pins anew (update() skips only states it
// has applied under the configuration in force).
TEST(DigitalOutputs, SameStatesUnderANewConfigurationDriveThePinsAnew) {
    DigitalOutputs outputs;
    DigitalOutputConfiguration config;
    config.functions = {0, 1, 2, 15};
    config.mask = 0x8007;
    outputs.configure(config);
    outputs.update(0x0001);
    EXPECT_EQ(outputs.levels(), 0b0001);
    outputs.update(0x0001);
    EXPECT_EQ(outputs.levels(), 0b0001);
    config.polarity = 0x8001; // ready/fault and A low active
    outputs.configure(config);
    outputs.update(0x0001);
    EXPECT_EQ(outputs.levels(), 0b1000);
    config.functions = {15, 1, 2, 0}; // A on output 1, ready/fault on output 4
    outputs.configure(config);
    outputs.update(0x0001);
    EXPECT_EQ(outputs.levels(), 0b0001);
}

TEST(DigitalOutputs, UnusedConfigurationDrivesNothing) {
    DigitalOutputs outputs;
    DigitalOutputConfiguration config;
    config.functions = {3, 10, 7, 8};
    config.mask = 0xFFFF;
    outputs.configure(config);
    outputs.update(0xFFFF);
    EXPECT_EQ(outputs.levels(), 0);
}

/// Feeds the marker a sequence of states at positions 10, 20, 30, …; returns its counter.
std::uint16_t feed(PositionMarker& marker, const std::vector<bool>& states) {
    std::int32_t position = 0;
    for (const bool state : states) {
        position += 10;
        marker.update(state, true, position);
    }
    return marker.counter();
}

// Table 8-90: the edge types, in Continuous mode (every edge of the kind captures).
TEST(PositionMarker, EdgeTypeSelectsTheCapturingEdges) {
    const struct {
        MarkerEdge edge;
        std::uint16_t counter;
        std::int32_t captured;
    } rows[] = {
        {MarkerEdge::Both, 4, 80}, {MarkerEdge::Rising, 2, 70}, {MarkerEdge::Falling, 2, 80}};
    for (const auto& row : rows) {
        PositionMarker marker;
        marker.configure(row.edge, MarkerMode::Continuous);
        // rising at 20 and 70, falling at 40 and 80
        EXPECT_EQ(feed(marker, {false, true, true, false, false, false, true, false}), row.counter);
        EXPECT_EQ(marker.captured(), row.captured);
    }
}

// Table 8-91.
TEST(PositionMarker, SingleModeCapturesTheFirstEdgeOnly) {
    PositionMarker marker;
    marker.configure(MarkerEdge::Rising, MarkerMode::Single);
    EXPECT_EQ(feed(marker, {true, false, true, false}), 1);
    EXPECT_EQ(marker.captured(), 10);
}

TEST(PositionMarker, MultipleModeCapturesUntilTheHistoryIsFull) {
    PositionMarker marker;
    marker.configure(MarkerEdge::Rising, MarkerMode::Multiple);
    EXPECT_EQ(feed(marker, {true, false, true, false, true, false, true}), 3);
    EXPECT_EQ(marker.captured(), 50);
    EXPECT_EQ(marker.history(1), 30);
    EXPECT_EQ(marker.history(2), 10);
}

TEST(PositionMarker, ContinuousModeShiftsTheOldestPositionOut) {
    PositionMarker marker;
    marker.configure(MarkerEdge::Rising, MarkerMode::Continuous);
    EXPECT_EQ(feed(marker, {true, false, true, false, true, false, true}), 4);
    EXPECT_EQ(marker.captured(), 70);
    EXPECT_EQ(marker.history(1), 50);
    EXPECT_EQ(marker.history(2), 30);
}

TEST(PositionMarker, SingleAndStopAsksForAStopAtItsCapture) {
    PositionMarker marker;
    marker.configure(MarkerEdge::Rising, MarkerMode::SingleAndStop);
    EXPECT_FALSE(marker.update(false, true, 5));
    EXPECT_TRUE(marker.update(true, true, 6));
    EXPECT_FALSE(marker.update(false, true, 7));
    EXPECT_FALSE(marker.update(true, true, 8));
    EXPECT_EQ(marker.captured(), 6);
}

TEST(PositionMarker, CounterWrittenZeroClearsAndCapturesAgain) {
    PositionMarker marker;
    marker.configure(MarkerEdge::Rising, MarkerMode::Single);
    feed(marker, {true, false});
    marker.counter_written(0);
    EXPECT_EQ(marker.captured(), 0);
    marker.update(true, true, 99);
    EXPECT_EQ(marker.captured(), 99);
    EXPECT_EQ(marker.counter(), 1);
}

// Table 8-89 bit 3: without its execution bit the marker does not capture.
TEST(PositionMarker, NotExecutedCapturesNothing) {
    PositionMarker marker;
    marker.update(true, false, 5);
    EXPECT_EQ(marker.counter(), 0);
}

// 8.2.58: homing resets the marker and suspends it until the homing ends.
TEST(PositionMarker, HomingResetsTheMarkerAndSuspendsIt) {
    PositionMarker marker;
    marker.configure(MarkerEdge::Both, MarkerMode::Continuous);
    feed(marker, {true});
    marker.homing_started();
    EXPECT_EQ(marker.captured(), 0);
    EXPECT_EQ(marker.counter(), 0);
    marker.update(false, true, 50);
    EXPECT_EQ(marker.counter(), 0);
    marker.set_homing(false);
    marker.update(true, true, 60);
    EXPECT_EQ(marker.captured(), 60);
}

// Table 8-96 bits: enable, operational mode << 1, interval mode << 3, direction << 5.
constexpr std::uint16_t compare_bits(unsigned operational, unsigned interval, unsigned direction) {
    return static_cast<std::uint16_t>(1U | operational << 1 | interval << 3 | direction << 5);
}

/// Moves the compare along `path` (one position per millisecond); the periods the output is on.
std::vector<int> pulses(const PositionCompareConfiguration& config,
                        const std::vector<std::int64_t>& path) {
    PositionCompare compare;
    compare.configure(config);
    std::vector<int> on;
    for (std::size_t i = 1; i < path.size(); ++i) {
        if (compare.update(static_cast<double>(i) * 1e-3, path[i - 1], path[i])) {
            on.push_back(static_cast<int>(i));
        }
    }
    return on;
}

TEST(PositionCompare, SinglePositionPulsesWhenPassedInAComparedDirection) {
    const std::vector<std::int64_t> there_and_back{0, 50, 100, 150, 100, 50, 0};
    const struct {
        unsigned direction;
        std::vector<int> on;
    } rows[] = {{0, {4}}, {1, {2}}, {2, {2, 4}}};
    for (const auto& row : rows) {
        EXPECT_EQ(pulses({.configuration = compare_bits(0, 0, row.direction), .reference = 100},
                         there_and_back),
                  row.on)
            << "direction dependency " << row.direction;
    }
}

TEST(PositionCompare, SequenceComparesTheIntervalsOfItsIntervalMode) {
    const std::vector<std::int64_t> up{-250, -150, -50, 50, 150, 250, 350, 450};
    const struct {
        unsigned interval;
        std::uint16_t repetitions;
        std::vector<int> on;
    } rows[] = {
        {1, 2, {3, 4, 5}},       // 0, 100, 200
        {0, 2, {1, 2, 3}},       // -200, -100, 0
        {2, 1, {2, 3, 4}},       // -100, 0, 100
        {1, 0, {3, 4, 5, 6, 7}}, // 0, 100, … endless
    };
    for (const auto& row : rows) {
        EXPECT_EQ(pulses({.configuration = compare_bits(1, row.interval, 2),
                          .reference = 0,
                          .interval_width = 100,
                          .repetitions = row.repetitions},
                         up),
                  row.on)
            << "interval mode " << row.interval;
    }
}

// 8.2.61 sub 5: rounded to 100 µs, at least 500 µs; sampled every millisecond.
TEST(PositionCompare, PulseWidthRoundedTo100MicrosecondsAtLeast500) {
    const std::vector<std::int64_t> path{0, 10, 10, 10, 10, 10, 10};
    const struct {
        std::uint16_t width;
        std::vector<int> on;
    } rows[] = {{0, {1}}, {549, {1}}, {1000, {1}}, {1050, {1, 2}}, {3000, {1, 2, 3}}};
    for (const auto& row : rows) {
        EXPECT_EQ(pulses({.configuration = compare_bits(0, 0, 2),
                          .reference = 5,
                          .pulse_width_us = row.width},
                         path),
                  row.on)
            << "pulse width " << row.width;
    }
}

TEST(PositionCompare, DisabledReservedOrWithoutIncrementalEncoderComparesNothing) {
    const std::vector<std::int64_t> path{0, 200};
    EXPECT_TRUE(pulses({.configuration = 0, .reference = 100}, path).empty());
    EXPECT_TRUE(pulses({.configuration = compare_bits(2, 0, 2), .reference = 100}, path).empty());
    EXPECT_TRUE(pulses({.configuration = compare_bits(0, 0, 3), .reference = 100}, path).empty());
    EXPECT_TRUE(
        pulses({.configuration = compare_bits(0, 0, 2), .reference = 100, .sensor_type = 4}, path)
            .empty());
}

constexpr double kMs = 1e-3;

// 8.2.72: released at power-on; Operation Enable after the fall time.
TEST(HoldingBrake, ReleasedAtPowerOnAndOperationAfterTheFallTime) {
    HoldingBrake brake;
    brake.configure(true, {.rise_time = 20, .fall_time = 30, .timeout = 65535}, {});
    EXPECT_TRUE(brake.engaged());
    EXPECT_TRUE(brake.power_stage(0, true, false, 0));
    EXPECT_FALSE(brake.engaged());
    EXPECT_FALSE(brake.operation_may_start(29 * kMs));
    EXPECT_TRUE(brake.operation_may_start(30 * kMs));
}

// From standstill: the brake engages at once, the power stage holds the axis for the rise time.
TEST(HoldingBrake, DisabledAtStandstillPowerStageHoldsForTheRiseTime) {
    HoldingBrake brake;
    brake.configure(true, {.rise_time = 20, .fall_time = 0, .timeout = 65535}, {});
    double now = 0;
    for (; now < 0.1; now += kMs) {
        brake.power_stage(now, true, false, 0);
    }
    const double off_request = now;
    for (; brake.power_stage(now, false, false, 0); now += kMs) {
        EXPECT_TRUE(brake.engaged());
    }
    EXPECT_NEAR(now - off_request, 20 * kMs, 1e-9);
    EXPECT_TRUE(brake.engaged());
}

// A moving axis disabled without a ramp coasts; the brake engages at standstill (0x2101) or after
// the brake timeout; a fault never holds the power stage.
TEST(HoldingBrake, DisabledWhileMovingCoastsUntilStandstillOrTimeout) {
    HoldingBrake brake;
    brake.configure(true, {.rise_time = 20, .fall_time = 0, .timeout = 40},
                    {.window = 30, .time_ms = 5, .timeout_ms = 1000});
    double now = 0;
    brake.power_stage(now, true, false, 1000);
    now += kMs;
    EXPECT_FALSE(brake.power_stage(now, false, false, 1000)) << "power stage off at once";
    EXPECT_FALSE(brake.engaged());
    for (int ms = 1; ms < 40; ++ms) {
        brake.power_stage(now + ms * kMs, false, false, 500);
    }
    EXPECT_FALSE(brake.engaged());
    brake.power_stage(now + 40 * kMs, false, false, 500);
    EXPECT_TRUE(brake.engaged()) << "brake timeout";

    HoldingBrake at_standstill;
    at_standstill.configure(true, {.rise_time = 20, .fall_time = 0, .timeout = 65535},
                            {.window = 30, .time_ms = 5, .timeout_ms = 1000});
    for (int ms = 0; ms < 10; ++ms) {
        at_standstill.power_stage(ms * kMs, true, false, 0);
    }
    EXPECT_FALSE(at_standstill.power_stage(10 * kMs, false, /*fault=*/true, 0));
    EXPECT_TRUE(at_standstill.engaged());
}

TEST(HoldingBrake, WithoutBrakeOutputThePowerStageFollowsAtOnce) {
    HoldingBrake brake;
    brake.configure(false, {}, {});
    EXPECT_TRUE(brake.power_stage(0, true, false, 0));
    EXPECT_TRUE(brake.operation_may_start(0));
    EXPECT_FALSE(brake.power_stage(kMs, false, false, 0));
}

// A configuration starts the standstill watch afresh, with a brake before or without one (which
// therefore need not watch): an axis at rest for 20 ms before it is disabled still coasts until
// it has stood still for the window time after the configuration.
TEST(HoldingBrake, ConfigurationStartsTheStandstillWatchAfresh) {
    const motion::StandstillWindow window{.window = 30, .time_ms = 5, .timeout_ms = 1000};
    const HoldingBrakeTiming timing{.rise_time = 20, .fall_time = 0, .timeout = 65535};
    for (const bool brake_before : {true, false}) {
        HoldingBrake brake;
        brake.configure(brake_before, timing, window);
        double now = 0;
        for (; now < 20 * kMs; now += kMs) {
            EXPECT_TRUE(brake.power_stage(now, true, false, 0));
        }
        brake.configure(true, timing, window);
        EXPECT_FALSE(brake.power_stage(now, false, false, 0)) << brake_before;
        EXPECT_FALSE(brake.engaged())
            << "coasting until standstill, brake before: " << brake_before;
        for (int ms = 1; ms <= 5; ++ms) {
            brake.power_stage(now + ms * kMs, false, false, 0);
        }
        EXPECT_TRUE(brake.engaged()) << "standstill for 5 ms, brake before: " << brake_before;
    }
}

} // namespace
} // namespace eposp::drives::epos2
