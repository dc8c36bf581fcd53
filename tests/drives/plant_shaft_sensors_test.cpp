#include "eposp/drives/plant/shaft_sensors.hpp"

#include <bitset>
#include <gtest/gtest.h>
#include <numbers>
#include <set>

namespace eposp::drives::plant {
namespace {

constexpr double kTurn = 2 * std::numbers::pi;

TEST(ShaftSensors, EncoderCountsFourQuadcountsPerPulse) {
    EXPECT_EQ(counts_per_turn(500), 2000);
    EXPECT_EQ(quadcounts(kTurn, 500), 2000);
    EXPECT_EQ(quadcounts(kTurn * 0.99999 / 2000, 500), 0); // just under one count
    EXPECT_EQ(quadcounts(kTurn * 1.00001 / 2000, 500), 1);
    EXPECT_EQ(quadcounts(-1e-9, 500), -1); // quantised downwards on both sides of zero
    EXPECT_EQ(quadcounts(-kTurn, 1024), -4096);
}

TEST(ShaftSensors, IndexPulsesOncePerRevolutionInBothDirections) {
    EXPECT_TRUE(index_passed(1999, 2000, 500));
    EXPECT_TRUE(index_passed(2000, 1999, 500));
    EXPECT_TRUE(index_passed(-1, 0, 500));
    EXPECT_FALSE(index_passed(1, 1999, 500));
    EXPECT_FALSE(index_passed(-1999, -1, 500));
    int pulses = 0;
    for (std::int64_t count = -5000; count < 5000; ++count) {
        pulses += index_passed(count, count + 1, 500) ? 1 : 0;
    }
    EXPECT_EQ(pulses, 5);
}

TEST(ShaftSensors, HallSensorsStepThroughSixStatesPerElectricalTurn) {
    constexpr int kPolePairs = 4;
    std::set<std::uint8_t> seen;
    std::uint8_t previous = hall_pattern(0, kPolePairs);
    int changes = 0;
    for (int i = 1; i <= 2400; ++i) {
        const std::uint8_t now = hall_pattern(kTurn * (i + 0.5) / 2400, kPolePairs);
        seen.insert(now);
        if (now != previous) {
            ++changes;
            EXPECT_EQ(std::bitset<3>(now ^ previous).count(), 1U) << "one sensor at a time";
        }
        previous = now;
    }
    EXPECT_EQ(seen, (std::set<std::uint8_t>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(changes, 6 * kPolePairs);
}

TEST(ShaftSensors, SwitchesTripAtTheirConfiguredPositions) {
    const SwitchLayout layout{-1000, 50000, 2000, true, std::nullopt};
    EXPECT_EQ(switch_states(layout, -1000), (SwitchStates{true, false, false}));
    EXPECT_EQ(switch_states(layout, -999), (SwitchStates{false, false, false}));
    EXPECT_EQ(switch_states(layout, 2000), (SwitchStates{false, false, true}));
    EXPECT_EQ(switch_states(layout, 50000), (SwitchStates{false, true, true}));
    EXPECT_EQ(switch_states(SwitchLayout{}, 1 << 30), SwitchStates{});
    const SwitchLayout below{std::nullopt, std::nullopt, 0, false, std::nullopt};
    EXPECT_TRUE(switch_states(below, -1).home);
    EXPECT_FALSE(switch_states(below, 0).home);
}

TEST(ShaftSensors, HomeCamIsActiveOverItsLengthOnly) {
    const SwitchLayout above{std::nullopt, std::nullopt, 100, true, 50};
    EXPECT_FALSE(switch_states(above, 99).home);
    EXPECT_TRUE(switch_states(above, 100).home);
    EXPECT_TRUE(switch_states(above, 149).home);
    EXPECT_FALSE(switch_states(above, 150).home);
    const SwitchLayout below{std::nullopt, std::nullopt, 100, false, 50};
    EXPECT_FALSE(switch_states(below, 100).home);
    EXPECT_TRUE(switch_states(below, 99).home);
    EXPECT_TRUE(switch_states(below, 50).home);
    EXPECT_FALSE(switch_states(below, 49).home);
}

} // namespace
} // namespace eposp::drives::plant
