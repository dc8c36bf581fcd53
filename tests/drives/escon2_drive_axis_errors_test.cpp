// The ESCON2's errors of table 110 whose causes lie in the axis and its configuration (ESCON2 FW
// spec 7.1): each with its error code, error register, history entry, reaction and recovery,
// in virtual time.
#include "escon2_drive_fixture.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <numbers>

namespace eposp::drives::escon2 {
namespace {

using namespace std::chrono_literals;

using namespace test;

constexpr std::uint16_t kEncoderInverted = 1U << 4;         // table 55
constexpr std::uint32_t kNoMainSensorSupervision = 1U << 8; // table 52
constexpr std::int32_t kRpm = 1000;

class Escon2AxisErrors : public test::Escon2DriveFixture {
protected:
    /// The reference axis with a brushed motor (the encoder alone, the main sensor), as the
    /// machine is built: `machine` changes it first.
    void start(const std::function<void(plant::AxisParameters&)>& machine = {}) {
        Escon2DriveConfig config;
        config.axis.plant.motor.kind = plant::MotorKind::BrushedDc;
        if (machine) {
            machine(config.axis);
        }
        Escon2DriveFixture::start(config);
    }
    double motor_rpm() const {
        return drive->axis().motor().state().speed * 60 / (2 * std::numbers::pi);
    }

    /// "Reset fault with Controlword": the error and its register bits go.
    void expect_fault_reset() {
        controlword(0x80);
        loop.run_for(2ms);
        EXPECT_EQ(state(), kSwitchOnDisabled);
        EXPECT_EQ(read<std::uint16_t>(0x603F), 0);
        EXPECT_EQ(read<std::uint8_t>(0x1001), 0u);
    }

    /// The motor, unpowered, slows down by its friction (at most a minute).
    void coast_to_rest() {
        for (int step = 0; step < 6000 && std::abs(motor_rpm()) >= 1; ++step) {
            loop.run_for(10ms);
        }
        ASSERT_LT(std::abs(motor_rpm()), 1);
    }
};

void mounted_the_other_way_round(plant::AxisParameters& axis) {
    axis.encoder_mounting.counts_against_motor = true;
}

// 7.1.27 "wrong setting of sensor polarity": an encoder mounted the other way round (the machine
// file's encoder.counts_against_motor) read with the maxon direction of 0x3010 sub 2 counts
// against the motor; the velocity loop drives it away until the supervision has seen a quarter
// turn (500 lines: 500 quadcounts) against the motor's turning.
TEST_F(Escon2AxisErrors, EncoderCountingAgainstTheMotorRaises7392MainSensorDirectionError) {
    start(mounted_the_other_way_round);
    enable();
    drive->set_velocity_set_value(kRpm);
    for (int ms = 0; ms < 1000 && state() == kOperationEnabled; ++ms) {
        loop.run_for(1ms);
    }
    expect_disabled_with(0x7392, 0b0010'0001);
    EXPECT_LT(std::abs(drive->axis().position_actual()), 1000) << "found within half a turn";
    expect_fault_reset();
    enable();
    loop.run_for(200ms);
    EXPECT_EQ(state(), kFault) << "the wrong setting trips again";
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0x7392);
}

// 0x3010 sub 2 bit 4 "Inverted (or encoder mounted on motor shaft)" matching the mounting: the
// axis runs as it does with a maxon encoder, both ways.
TEST_F(Escon2AxisErrors, EncoderDirectionMatchingTheMountingRunsNormally) {
    start(mounted_the_other_way_round);
    write(0x3010, 2, kEncoderInverted);
    enable();
    drive->set_velocity_set_value(kRpm);
    loop.run_for(300ms);
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_NEAR(read<std::int32_t>(0x606C), kRpm, 10);
    EXPECT_NEAR(motor_rpm(), kRpm, 10) << "the motor turns positive on a positive demand";
    drive->set_velocity_set_value(-kRpm);
    loop.run_for(500ms);
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_NEAR(motor_rpm(), -kRpm, 10);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 0u);
}

// The same setting on a maxon-mounted encoder is the wrong one.
TEST_F(Escon2AxisErrors, InvertedDirectionOnAMaxonMountedEncoderRaises7392) {
    start();
    write(0x3010, 2, kEncoderInverted);
    enable();
    drive->set_velocity_set_value(kRpm);
    loop.run_for(200ms);
    expect_disabled_with(0x7392, 0b0010'0001);
}

// Table 52 bit 8 switches the main sensor supervision off, and with it 7.1.27: the axis runs
// away unsupervised, the motor ever faster the commanded way while the encoder reads it turning
// the other.
TEST_F(Escon2AxisErrors, WithTheMainSensorSupervisionDisabledNo7392) {
    start(mounted_the_other_way_round);
    write(0x3000, 4, kNoMainSensorSupervision);
    enable();
    drive->set_velocity_set_value(kRpm);
    loop.run_for(200ms);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0);
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_GT(motor_rpm(), 5 * kRpm);
    EXPECT_LT(read<std::int32_t>(0x606C), -5 * kRpm);
}

// 7.1.21: the enable calibrates the current offset as the power stage comes on. Disabled at
// 1000 rpm and enabled again at once, the motor still coasts: the warning (bit 7, bit 31 of its
// history entry), the drive runs on. Stopped and enabled again at standstill, the calibration
// succeeds and clears it.
TEST_F(Escon2AxisErrors, EnablingWhileTheMotorTurnsRaises7280UntilAnEnableAtStandstill) {
    start();
    enable();
    drive->set_velocity_set_value(kRpm);
    loop.run_for(200ms);
    controlword(0x00);
    loop.run_for(1ms);
    ASSERT_EQ(drive->axis().mode(), plant::ControlMode::PowerOff);
    enable();
    loop.run_for(2ms);
    EXPECT_GT(motor_rpm(), 500) << "still coasting";
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_EQ(drive->axis().mode(), plant::ControlMode::Velocity);
    EXPECT_NE(read<std::uint16_t>(0x6041) & 0x80, 0) << "warning";
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0x7280);
    EXPECT_EQ(read<std::uint8_t>(0x1001), 0b0000'0001);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 1u);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1), 0x8000'7280u) << "a warning: bit 31 set";

    controlword(0x8F); // Clear warning (table 8) does not: it auto clears (table 110)
    controlword(0x0F);
    loop.run_for(1ms);
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0x7280);

    drive->set_velocity_set_value(0);
    loop.run_for(300ms);
    ASSERT_LT(std::abs(motor_rpm()), 1);
    controlword(0x00);
    loop.run_for(1ms);
    enable();
    loop.run_for(2ms);
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_EQ(read<std::uint16_t>(0x6041) & 0x80, 0);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0);
    EXPECT_EQ(read<std::uint8_t>(0x1001), 0u);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 1u) << "the history keeps the entry";
}

// An enable from rest raises nothing.
TEST_F(Escon2AxisErrors, EnablingAtStandstillRaisesNo7280) {
    start();
    enable();
    loop.run_for(2ms);
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 0u);
}

// 7.1.4: a short of the motor winding trips the power stage protection once the power stage
// drives the motor: "d", register 0000 0011b. The fault reset is allowed (the disabled power
// stage sees nothing); enabling again trips again until the winding is repaired.
TEST_F(Escon2AxisErrors, ShortedWindingRaises2320WhenThePowerStageDrivesTheMotor) {
    start();
    enable();
    drive->set_velocity_set_value(kRpm);
    loop.run_for(200ms);
    drive->short_motor_winding(true);
    expect_disabled_with(0x2320, 0b0000'0011);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 1u);
    expect_fault_reset();
    coast_to_rest(); // an enable while it turns would add 0x7280
    EXPECT_EQ(state(), kSwitchOnDisabled) << "nothing found with the power stage off";
    enable();
    expect_disabled_with(0x2320, 0b0000'0011);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 2u) << "a new occurrence";
    drive->short_motor_winding(false);
    expect_fault_reset();
    enable();
    loop.run_for(200ms);
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_NEAR(motor_rpm(), kRpm, 10);
}

} // namespace
} // namespace eposp::drives::escon2
