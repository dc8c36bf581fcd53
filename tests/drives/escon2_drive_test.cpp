// The running ESCON2 as its host sees it (the dictionary, written as over USB) in virtual time:
// device control (2.2), I/O Velocity Mode and I/O Current Mode (chapter 3) on the reference
// axis, and the errors the drive raises (7.1).
#include "eposp/canopen/store_restore_objects.hpp"
#include "escon2_drive_fixture.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>

namespace eposp::drives::escon2 {
namespace {

using canopen::AbortCode;
using namespace std::chrono_literals;

// Table 8.
constexpr std::uint16_t kShutdown = 0x06;
constexpr std::uint16_t kEnableOperation = 0x0F;
constexpr std::uint16_t kDisableOperation = 0x07;
constexpr std::uint16_t kQuickStop = 0x02;
constexpr std::uint16_t kFaultReset = 0x80;
// Table 6 (bits 0 - 3, 5, 6) and table 99.
using namespace test;
constexpr std::uint16_t kSwitchedOn = 0x0023;
constexpr std::uint16_t kQuickStopActive = 0x0007;
constexpr std::uint16_t kInternalLimitActive = 1U << 11;
constexpr std::uint16_t kFollowsCommandValue = 1U << 12;

class Escon2DriveTest : public test::Escon2DriveFixture {
protected:
    Escon2DriveTest() { start(); }

    std::int32_t velocity_demand() const { return read<std::int32_t>(0x606B); }
    std::int32_t velocity_actual() const { return read<std::int32_t>(0x606C); }
    std::int32_t current_actual() const { return read<std::int32_t>(0x30D1, 2); }

    void enable() {
        Escon2DriveFixture::enable();
        loop.run_for(1ms);
    }
    /// Runs period by period until `done`; the milliseconds it took, or -1 after `limit`.
    template <typename Done>
    int milliseconds_until(Done done, int limit = 5000) {
        for (int ms = 0; ms <= limit; ++ms) {
            if (done()) {
                return ms;
            }
            loop.run_for(1ms);
        }
        return -1;
    }
};

// 2.2 transitions 0, 1; table 100 default.
TEST_F(Escon2DriveTest, PowersUpInSwitchOnDisabledInIoVelocityMode) {
    run(2ms);
    EXPECT_EQ(statusword() & kStateMask, kSwitchOnDisabled);
    EXPECT_EQ(statusword() & 0x0100, 0) << "bit 8 reserved";
    EXPECT_EQ(read<std::int8_t>(0x6061), -121);
    EXPECT_EQ(drive->axis().mode(), plant::ControlMode::PowerOff);
}

// Table 7 transitions 2, 3, 4: the power stage on at once, the command value followed.
TEST_F(Escon2DriveTest, ShutdownAndEnableOperationPowerTheMotor) {
    enable();
    EXPECT_EQ(statusword() & kStateMask, kOperationEnabled);
    EXPECT_NE(statusword() & 0x0010, 0) << "voltage enabled";
    EXPECT_NE(statusword() & kFollowsCommandValue, 0);
    EXPECT_EQ(drive->axis().mode(), plant::ControlMode::Velocity);
    controlword(kDisableOperation); // 5: slows down from rest at once
    run(2ms);
    EXPECT_EQ(statusword() & kStateMask, kSwitchedOn);
    EXPECT_EQ(statusword() & kFollowsCommandValue, 0);
}

// 3.3: the ramp reaches the set value after |Δv| / profile acceleration: 1000 rpm at the default
// 10'000 rpm/s in 100 ms, and the motor follows it.
TEST_F(Escon2DriveTest, VelocityRampReachesTheSetValueWhenTheAccelerationSays) {
    enable();
    drive->set_velocity_set_value(1000);
    run(1ms);
    const int ramp = milliseconds_until([this] { return velocity_demand() >= 1000; });
    EXPECT_GE(ramp, 99);
    EXPECT_LE(ramp, 100);
    run(500ms);
    EXPECT_NEAR(read<std::int32_t>(0x30D3, 1), 1000, 10) << "averaged actual velocity";
    EXPECT_NE(statusword() & kFollowsCommandValue, 0);
    EXPECT_EQ(statusword() & kInternalLimitActive, 0);
}

// 3.3: slowing down takes the profile deceleration: 1000 rpm at 5000 rpm/s in 200 ms.
TEST_F(Escon2DriveTest, VelocityRampSlowsDownWithTheProfileDeceleration) {
    ASSERT_EQ(try_write(0x6084, 0, std::uint32_t{5000}), AbortCode::None);
    enable();
    drive->set_velocity_set_value(1000);
    run(200ms);
    drive->set_velocity_set_value(0);
    run(1ms);
    const int ramp = milliseconds_until([this] { return velocity_demand() <= 0; });
    EXPECT_GE(ramp, 199);
    EXPECT_LE(ramp, 200);
}

// 6.2.75: max acceleration bounds the profile acceleration (2000 rpm/s: 500 ms to 1000 rpm).
TEST_F(Escon2DriveTest, MaxAccelerationBoundsTheRamp) {
    ASSERT_EQ(try_write(0x60C5, 0, std::uint32_t{2000}), AbortCode::None);
    enable();
    drive->set_velocity_set_value(1000);
    run(1ms);
    const int ramp = milliseconds_until([this] { return velocity_demand() >= 1000; });
    EXPECT_GE(ramp, 499);
    EXPECT_LE(ramp, 500);
}

// Table 19: the set value beyond max motor speed is limited to it, and bit 11 says so.
TEST_F(Escon2DriveTest, MaxMotorSpeedLimitsTheSetValueWithBit11) {
    ASSERT_EQ(try_write(0x6080, 0, std::uint32_t{2000}), AbortCode::None);
    enable();
    drive->set_velocity_set_value(3000);
    run(400ms);
    EXPECT_EQ(velocity_demand(), 2000);
    EXPECT_NE(statusword() & kInternalLimitActive, 0);
    drive->set_velocity_set_value(1500);
    run(2ms);
    EXPECT_EQ(statusword() & kInternalLimitActive, 0);
}

// Table 19 "PWM max duty cycle": at 9 V the reference motor cannot reach 4000 rpm (its back-EMF
// alone needs about 9.4 V, more than 95 % of 9 V); the duty cycle stays at 950 ‰ (table 97) and
// bit 11 says so.
TEST_F(Escon2DriveTest, LowSupplyLimitsAtThePwmMaxDutyCycleWithBit11) {
    drive->set_supply_voltage(9);
    enable();
    drive->set_velocity_set_value(4000);
    run(1s);
    EXPECT_LT(velocity_actual(), 3900);
    EXPECT_EQ(read<std::uint16_t>(0x3203, 1), 950u);
    EXPECT_NE(statusword() & kInternalLimitActive, 0);
    drive->set_velocity_set_value(1000);
    run(1s);
    EXPECT_EQ(statusword() & kInternalLimitActive, 0);
    EXPECT_LT(read<std::uint16_t>(0x3203, 1), 950u);
}

// 6.2.74: the velocity offset is added to the target velocity.
TEST_F(Escon2DriveTest, VelocityOffsetIsAddedToTheTarget) {
    enable();
    drive->set_velocity_set_value(500);
    drive->set_velocity_offset(300);
    run(200ms);
    EXPECT_EQ(velocity_demand(), 800);
    EXPECT_EQ(read<std::int32_t>(0x60FF), 500);
    EXPECT_EQ(read<std::int32_t>(0x60B1), 300);
}

// 2.3, table 103: in milli rev/min the same motion reads a thousand times larger.
TEST_F(Escon2DriveTest, MilliRpmVelocityUnits) {
    ASSERT_EQ(try_write(0x60A9, 0, std::uint32_t{0xFDB4'4700}), AbortCode::None);
    enable();
    drive->set_velocity_set_value(1'000'000);
    run(300ms);
    EXPECT_EQ(velocity_demand(), 1'000'000);
    EXPECT_NEAR(read<std::int32_t>(0x30D3, 1), 1'000'000, 20'000);
}

// 3.4: the current follows a step of the target current within milliseconds (the current loop
// of the reference axis, ~800 Hz), and the motor accelerates.
TEST_F(Escon2DriveTest, CurrentModeStepResponse) {
    ASSERT_EQ(try_write(0x6060, 0, std::int8_t{-120}), AbortCode::None);
    EXPECT_EQ(read<std::int8_t>(0x6061), -120);
    enable();
    EXPECT_EQ(drive->axis().mode(), plant::ControlMode::Current);
    drive->set_current_set_value(500);
    run(1ms); // taken at the next period
    run(5ms);
    EXPECT_EQ(read<std::int32_t>(0x30D0), 500) << "current demand value";
    EXPECT_NEAR(current_actual(), 500, 15);
    EXPECT_GT(velocity_actual(), 0);
}

// 3.4, 6.2.25, table 25: target + offset, limited to the output current limit with bit 11.
TEST_F(Escon2DriveTest, CurrentOffsetAddsAndOutputCurrentLimitCaps) {
    ASSERT_EQ(try_write(0x6060, 0, std::int8_t{-120}), AbortCode::None);
    enable();
    drive->set_current_set_value(300);
    drive->set_current_offset(200);
    run(6ms);
    EXPECT_EQ(read<std::int32_t>(0x30D0), 500);
    EXPECT_EQ(statusword() & kInternalLimitActive, 0);
    drive->set_current_set_value(-5000);
    run(6ms);
    EXPECT_EQ(read<std::int32_t>(0x30D0), -3000) << "the reference axis' 3 A limit";
    EXPECT_NE(statusword() & kInternalLimitActive, 0);
}

// Table 25: max motor speed caps the current mode through the velocity controller.
TEST_F(Escon2DriveTest, CurrentModeStopsAcceleratingAtMaxMotorSpeed) {
    ASSERT_EQ(try_write(0x6080, 0, std::uint32_t{1000}), AbortCode::None);
    ASSERT_EQ(try_write(0x6060, 0, std::int8_t{-120}), AbortCode::None);
    enable();
    drive->set_current_set_value(1000);
    run(1s);
    EXPECT_NEAR(read<std::int32_t>(0x30D3, 1), 1000, 40);
    EXPECT_NE(statusword() & kInternalLimitActive, 0);
}

// Table 7 transition 11: quick stop ramps down with 0x6085 and stays in Quick stop active;
// 16 enables again.
TEST_F(Escon2DriveTest, QuickStopRampsDownWithTheQuickStopDeceleration) {
    ASSERT_EQ(try_write(0x6085, 0, std::uint32_t{20'000}), AbortCode::None);
    enable();
    drive->set_velocity_set_value(1000);
    run(300ms);
    controlword(kQuickStop);
    EXPECT_EQ(statusword() & kStateMask, kQuickStopActive);
    run(1ms);
    const int ramp = milliseconds_until([this] { return velocity_demand() <= 0; });
    EXPECT_GE(ramp, 48);
    EXPECT_LE(ramp, 50);
    run(100ms);
    EXPECT_EQ(statusword() & kStateMask, kQuickStopActive);
    EXPECT_NEAR(velocity_actual(), 0, 60);
    controlword(kEnableOperation); // 16
    run(300ms);
    EXPECT_EQ(velocity_demand(), 1000);
}

// Transition 5 with the disable operation option code's slow down: the profile deceleration,
// then Switched on.
TEST_F(Escon2DriveTest, DisableOperationSlowsDownFirst) {
    enable();
    drive->set_velocity_set_value(1000);
    run(300ms);
    controlword(kDisableOperation);
    run(50ms);
    EXPECT_EQ(statusword() & kStateMask, kOperationEnabled) << "still slowing down";
    run(60ms);
    EXPECT_EQ(statusword() & kStateMask, kSwitchedOn);
}

// 7.1.28, table 110 "f": quick stop ramp (fault reaction active, power on), then Fault; the
// error's code, register bits and history entry; fault reset clears it (15).
TEST_F(Escon2DriveTest, LimitSwitchErrorQuickStopsThenFaultAndResets) {
    enable();
    drive->set_velocity_set_value(1000);
    run(300ms);
    drive->raise_device_error(0x8A80);
    EXPECT_EQ(statusword() & 0x007F, 0x001F) << "fault reaction active, power on";
    run(150ms);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0x8A80);
    EXPECT_EQ(read<std::uint8_t>(0x1001), 0b0010'0001);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1), 0x8A80u);
    controlword(kFaultReset);
    EXPECT_EQ(statusword() & kStateMask, kSwitchOnDisabled);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0);
    EXPECT_EQ(read<std::uint8_t>(0x1001), 0);
}

// Table 110 "d": disabled at once; an error needing a device reset survives a fault reset.
TEST_F(Escon2DriveTest, HardwareErrorDisablesAndNeedsADeviceReset) {
    enable();
    drive->raise_device_error(0x5480);
    run(2ms);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    EXPECT_EQ(drive->axis().mode(), plant::ControlMode::PowerOff);
    controlword(kFaultReset);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    drive->start(); // power cycle
    EXPECT_EQ(statusword() & kStateMask, kSwitchOnDisabled);
}

// 7.1.41: I/O Velocity Mode needs the velocity controller.
TEST_F(Escon2DriveTest, VelocityModeWithoutVelocityControllerIsNotSupported) {
    ASSERT_EQ(try_write(0x3000, 2, std::uint32_t{0x0000'0001}), AbortCode::None);
    enable();
    run(2ms);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0xFF0D);
    controlword(kFaultReset);
    ASSERT_EQ(try_write(0x6060, 0, std::int8_t{-120}), AbortCode::None);
    enable();
    EXPECT_EQ(statusword() & kStateMask, kOperationEnabled) << "current mode runs without";
}

// 7.1.21, table 99 bit 7: a warning leaves the state alone and clears with its cause; 7.1.36:
// the system overload warning clears with the Clear warning command of table 8.
TEST_F(Escon2DriveTest, WarningsSetBit7AndClear) {
    enable();
    drive->raise_device_error(0x7280);
    run(1ms);
    EXPECT_NE(statusword() & kWarning, 0);
    EXPECT_EQ(statusword() & kStateMask, kOperationEnabled);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1), 0x8000'7280u);
    drive->clear_warning(0x7280);
    run(1ms);
    EXPECT_EQ(statusword() & kWarning, 0);
    drive->raise_device_error(0xFF01);
    run(1ms);
    controlword(kEnableOperation | kFaultReset);
    controlword(kEnableOperation);
    EXPECT_EQ(statusword() & kWarning, 0);
    EXPECT_EQ(statusword() & kStateMask, kOperationEnabled);
}

// «Power Disable» objects and the restore of 6.2.6 are refused while the power stage is on.
TEST_F(Escon2DriveTest, ConfigurationIsRefusedWhileEnabled) {
    enable();
    EXPECT_EQ(try_write(0x6402, 0, std::uint16_t{1}), AbortCode::DeviceState);
    EXPECT_EQ(try_write(0x1011, 1, canopen::kLoadSignature), AbortCode::DeviceState);
    EXPECT_EQ(try_write(0x3001, 1, std::uint32_t{1000}), AbortCode::None);
}

// 7.1.17: a damaged store is refused at power-up, the defaults apply and 0x6380 is raised.
TEST_F(Escon2DriveTest, DamagedParameterStoreRaisesLoadingParameterFailed) {
    ASSERT_EQ(try_write(0x210C, 1, std::uint32_t{42}), AbortCode::None);
    ASSERT_EQ(try_write(0x1010, 1, canopen::kSaveSignature), AbortCode::None);
    drive->start();
    EXPECT_EQ(read<std::uint32_t>(0x210C, 1), 42u) << "the store applies";
    {
        std::ofstream damaged(parameter_file(), std::ios::binary | std::ios::trunc);
        damaged << "not a parameter store";
    }
    drive->start();
    run(2ms);
    EXPECT_EQ(read<std::uint32_t>(0x210C, 1), 0u);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0x6380);
    EXPECT_EQ(statusword() & kStateMask, kFault);
}

// 6.2.13.4 bit 0: inverse polarity turns the axis the other way on the same set value and
// reports its velocity in the commanded sense.
TEST_F(Escon2DriveTest, InversePolarityTurnsTheOtherWay) {
    ASSERT_EQ(try_write(0x3000, 4, std::uint32_t{1}), AbortCode::None);
    enable();
    drive->set_velocity_set_value(500);
    run(300ms);
    EXPECT_LT(drive->axis().velocity_actual(), 0);
    EXPECT_NEAR(velocity_actual(), 500, 40);
}

// Tables 41 - 97 on the smallest hardware: its own limits (6 A output current limit, 31 V
// overvoltage, no power stage I²t, 90 % PWM) and the same motion.
class Escon2DriveHardware : public test::Escon2DriveFixture {};

TEST_F(Escon2DriveHardware, NanoRunsTheVelocityModeWithItsOwnLimits) {
    Escon2DriveConfig config;
    config.dictionary.hardware = Escon2Hardware::Nano24_2;
    start(config);
    auto& od = drive->objects();
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 2), 0x1103'1000u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x3001, 2), 3000u) << "the machine's 3 A, within 6 A";
    ASSERT_EQ(od.write(0x6040, 0, canopen::encode(kShutdown)), AbortCode::None);
    ASSERT_EQ(od.write(0x6040, 0, canopen::encode(kEnableOperation)), AbortCode::None);
    drive->set_velocity_set_value(1000);
    loop.run_for(500ms);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x6041, 0) & kStateMask, kOperationEnabled);
    EXPECT_NEAR(od.get_as<std::int32_t>(0x30D3, 1), 1000, 10);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x3201, 1), 0u) << "no power stage I2t on the Nano";
    drive->set_supply_voltage(32);
    loop.run_for(2ms);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x603F, 0), 0x3210) << "above the Nano's 31 V";
}

} // namespace
} // namespace eposp::drives::escon2
