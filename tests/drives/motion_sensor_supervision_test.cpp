// The shared sensor supervision's Hall angle check (ESCON2 FW spec 7.1.24, EPOS2 FW spec 4.2.29)
// fed the shaft's angle directly: exact sensors pass either way at any sampling, while Hall
// sensors wired in the wrong order or a frozen encoder are found.
#include "eposp/drives/motion/sensor_supervision.hpp"

#include <gtest/gtest.h>
#include <numbers>
#include <optional>

namespace eposp::drives::motion {
namespace {

constexpr int kPolePairs = 3;
constexpr double kTurn = 2 * std::numbers::pi;

class HallAngleCheck : public ::testing::Test {
protected:
    HallAngleCheck() {
        supervision.configure({.encoder_pulses = 500,
                               .encoder = true,
                               .encoder_index = false,
                               .hall_sensors = true,
                               .breach_supervision = false,
                               .hall_angle = true,
                               .pole_pairs = kPolePairs});
        supervision.restart(0, plant::hall_pattern(0, kPolePairs), faults);
    }

    /// Moves from `from` to `to` in steps of `step` radians; the first fault found.
    std::optional<SensorFault> move(double from, double to, double step,
                                    std::uint8_t (*wiring)(std::uint8_t) = nullptr) {
        const double direction = to > from ? 1 : -1;
        for (double angle = from; direction * (to - angle) > 0; angle += direction * step) {
            std::uint8_t pattern = plant::hall_pattern(angle, kPolePairs);
            if (wiring != nullptr) {
                pattern = wiring(pattern);
            }
            if (const auto fault = supervision.update(angle, pattern, faults)) {
                return fault;
            }
        }
        return std::nullopt;
    }

    SensorSupervision supervision;
    plant::SensorFaults faults;
};

std::uint8_t sensors_1_and_2_swapped(std::uint8_t pattern) {
    return static_cast<std::uint8_t>((pattern & 0b100) | ((pattern & 1) << 1) |
                                     ((pattern >> 1) & 1));
}

TEST(HallSector, IsTheInverseOfThePatternAndRefusesImpossibleCombinations) {
    for (int sector = 0; sector < 6; ++sector) {
        const double angle = (sector + 0.5) / 6 * kTurn;
        EXPECT_EQ(plant::hall_sector(plant::hall_pattern(angle, 1)), sector);
    }
    EXPECT_EQ(plant::hall_sector(0b000), std::nullopt);
    EXPECT_EQ(plant::hall_sector(0b111), std::nullopt);
}

// Samples a degree apart and samples three sectors apart (a fast motor read every ms) alike.
TEST_F(HallAngleCheck, ExactSensorsPassBothWaysAtAnySampling) {
    EXPECT_EQ(move(0, 10 * kTurn, kTurn / 360), std::nullopt);
    EXPECT_EQ(move(10 * kTurn, -5 * kTurn, kTurn / 360), std::nullopt);
    EXPECT_EQ(move(-5 * kTurn, 20 * kTurn, kTurn / kPolePairs / 2.1), std::nullopt);
}

// Valid patterns, but the sequence runs backwards against the encoder.
TEST_F(HallAngleCheck, SwappedHallSensorsAreFoundWithinAnElectricalTurn) {
    EXPECT_EQ(move(0, kTurn / kPolePairs, kTurn / 360, sensors_1_and_2_swapped),
              SensorFault::HallAngle);
}

// A broken encoder, the breach supervision off: its angle stands while the Halls go on.
TEST_F(HallAngleCheck, AFrozenEncoderIsFoundWithinAnElectricalTurn) {
    ASSERT_EQ(move(0, kTurn, kTurn / 360), std::nullopt);
    faults.encoder_broken = true;
    EXPECT_EQ(move(kTurn, kTurn + kTurn / kPolePairs, kTurn / 360), SensorFault::HallAngle);
}

// An encoder with index: the resolution is checked at the second index pulse, after which only a
// breach is left to find; a line broken then is still found, and a wrong resolution at the
// second index is still an error (the index checks run while they are pending).
TEST(EncoderSupervision, ABreachAfterTheIndexChecksIsStillFound) {
    const auto run = [](std::optional<int> mounted_pulses) {
        SensorSupervision supervision;
        supervision.configure({.encoder_pulses = 500, .encoder = true, .encoder_index = true});
        plant::SensorFaults faults{.encoder_pulses = mounted_pulses};
        supervision.restart(0.1, 0, faults);
        for (double angle = 0.1; angle < 3.5 * kTurn; angle += 0.01) {
            if (const auto fault = supervision.update(angle, 0, faults)) {
                return std::optional{*fault};
            }
        }
        faults.encoder_broken = true;
        return supervision.update(3.5 * kTurn, 0, faults);
    };
    EXPECT_EQ(run(std::nullopt), SensorFault::EncoderBreach) << "past two index pulses";
    EXPECT_EQ(run(512), SensorFault::EncoderResolution) << "found at the second index";
}

} // namespace
} // namespace eposp::drives::motion
