// The ESCON2's inputs and outputs wired into the running drive (chapter 4, 6.2.26 - 6.2.54):
// the I/O classes configured from the dictionary, commanding the modes and the device control,
// raising their errors, and showing the drive's state on the outputs, in virtual time.
#include "escon2_drive_fixture.hpp"

#include <chrono>
#include <gtest/gtest.h>

namespace eposp::drives::escon2 {
namespace {

using namespace std::chrono_literals;

using namespace test;

class Escon2DriveIo : public test::Escon2DriveFixture {
protected:
    Escon2DriveIo() { start(); }
};

// Table 59 "Drive enable": the input enables and disables the drive (after its 1 ms filter).
TEST_F(Escon2DriveIo, DriveEnableInputEnablesAndDisables) {
    write(0x3142, 3, std::uint8_t{27});
    drive->set_digital_input(3, true);
    run(1ms);
    EXPECT_EQ(state(), kSwitchOnDisabled) << "not held for the filter time yet";
    run(2ms);
    EXPECT_EQ(state(), kOperationEnabled);
    EXPECT_NE(read<std::uint32_t>(0x3143) & (1U << 27), 0u);
    drive->set_digital_input(3, false);
    run(3ms);
    EXPECT_EQ(state(), kSwitchOnDisabled);
}

// Table 59 "Drive enable ... or clear errors in Fault state".
TEST_F(Escon2DriveIo, DriveEnableClearsAFault) {
    write(0x3142, 3, std::uint8_t{27});
    drive->set_digital_input(3, true);
    run(3ms);
    drive->raise_device_error(0x1000);
    run(2ms);
    ASSERT_EQ(state(), kFault);
    drive->set_digital_input(3, false);
    run(3ms);
    drive->set_digital_input(3, true);
    run(3ms);
    EXPECT_EQ(state(), kSwitchOnDisabled);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0);
}

// 6.2.48: analog input 1 as velocity set value, −10 V … +10 V to −2000 … +2000 rpm: 5 V is
// 1000 rpm in Target velocity, and the ramp follows.
TEST_F(Escon2DriveIo, AnalogInputSetsTheTargetVelocity) {
    write(0x3161, 1, std::uint8_t{9});
    write(0x31B0, 2, std::int32_t{-2000});
    write(0x31B0, 4, std::int32_t{2000});
    drive->set_analog_input(1, 5.0);
    enable();
    run(200ms);
    EXPECT_EQ(read<std::int32_t>(0x60FF), 1000);
    EXPECT_EQ(read<std::int32_t>(0x606B), 1000);
    EXPECT_EQ(read<std::int16_t>(0x3160, 1), 5000);
}

// 6.2.46: a 1 kHz PWM at 50 % on digital input 1 through 10 % → 0 mA, 90 % → 2000 mA commands
// 1000 mA in I/O Current Mode.
TEST_F(Escon2DriveIo, PwmInputSetsTheTargetCurrent) {
    write(0x6060, 0, std::int8_t{-120});
    write(0x3142, 1, std::uint8_t{36});
    write(0x3184, 4, std::int32_t{2000});
    drive->set_pwm_signal(1, PwmSignal{.frequency = 1000, .duty_cycle = 50});
    enable();
    run(20ms);
    EXPECT_EQ(read<std::int32_t>(0x30F0), 1000);
    EXPECT_EQ(read<std::int32_t>(0x30D0), 1000);
    EXPECT_EQ(read<std::uint32_t>(0x314B, 1), 10'000u) << "0.1 Hz";
    EXPECT_EQ(read<std::uint16_t>(0x314C, 1), 500u) << "0.1 %";
}

// 7.1.30: a PWM frequency above 10 kHz is a warning (bit 7) that clears with its cause.
TEST_F(Escon2DriveIo, PwmFrequencyOutOfRangeIsAWarning) {
    write(0x3142, 1, std::uint8_t{32});
    drive->set_pwm_signal(1, PwmSignal{.frequency = 20'000, .duty_cycle = 50});
    run(10ms);
    EXPECT_NE(read<std::uint16_t>(0x6041) & kWarning, 0);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0x8A89);
    drive->set_pwm_signal(1, PwmSignal{.frequency = 1000, .duty_cycle = 50});
    run(10ms);
    EXPECT_EQ(read<std::uint16_t>(0x6041) & kWarning, 0);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1), 0x8000'8A89u);
}

// Table 61: the velocity set value switches select Set velocity value 0 - 3 into 0x60FF.
TEST_F(Escon2DriveIo, SetValueSwitchesSelectTheFixedVelocities) {
    write(0x3142, 3, std::uint8_t{12});
    write(0x3142, 4, std::uint8_t{13});
    for (std::uint8_t sub = 1; sub <= 4; ++sub) {
        write(0x3146, sub, std::int32_t{100 * (sub - 1) + 50});
    }
    run(3ms);
    EXPECT_EQ(read<std::int32_t>(0x60FF), 50);
    drive->set_digital_input(3, true);
    run(3ms);
    EXPECT_EQ(read<std::int32_t>(0x60FF), 150);
    drive->set_digital_input(4, true);
    run(3ms);
    EXPECT_EQ(read<std::int32_t>(0x60FF), 350);
}

// Table 59 [d]: with Direction mapped and inactive a positive set value is inverted.
TEST_F(Escon2DriveIo, DirectionInputTurnsThePositiveSetValue) {
    write(0x3142, 2, std::uint8_t{29});
    write(0x3161, 1, std::uint8_t{9});
    write(0x31B0, 2, std::int32_t{-2000});
    write(0x31B0, 4, std::int32_t{2000});
    drive->set_analog_input(1, 5.0);
    run(3ms);
    EXPECT_EQ(read<std::int32_t>(0x60FF), -1000);
    drive->set_digital_input(2, true);
    run(3ms);
    EXPECT_EQ(read<std::int32_t>(0x60FF), 1000);
}

// 7.1.28: the negative limit switch while the drive runs: quick stop, then Fault 0x8A80.
TEST_F(Escon2DriveIo, LimitSwitchInputStopsTheDriveWithItsError) {
    write(0x3142, 4, std::uint8_t{0});
    enable();
    drive->set_velocity_set_value(500);
    run(100ms);
    drive->set_digital_input(4, true);
    run(200ms);
    EXPECT_EQ(state(), kFault);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0x8A80);
    EXPECT_EQ(read<std::uint32_t>(0x60FD) & 1U, 1u);
}

// Table 65: ready/fault is active unless in fault; limitation follows statusword bit 11.
TEST_F(Escon2DriveIo, ReadyFaultAndLimitationOutputs) {
    write(0x3151, 1, std::uint8_t{25});
    write(0x3151, 2, std::uint8_t{26});
    write(0x6080, 0, std::uint32_t{500});
    enable();
    drive->set_velocity_set_value(1000);
    run(10ms);
    EXPECT_TRUE(drive->digital_output(1));
    EXPECT_TRUE(drive->digital_output(2)) << "set value above max motor speed";
    drive->raise_device_error(0x1000);
    run(2ms);
    EXPECT_FALSE(drive->digital_output(1));
}

// 6.2.43, 6.2.52: general purpose voltage and the velocity monitor (0 → 0 V, 2000 rpm → 4 V).
TEST_F(Escon2DriveIo, AnalogOutputsShowTheGeneralPurposeVoltageAndTheVelocity) {
    write(0x3172, 2, std::int16_t{-1500});
    write(0x3171, 1, std::uint8_t{8});
    write(0x31C1, 2, std::int32_t{0});
    write(0x31C1, 3, std::int32_t{2000});
    write(0x31C1, 4, std::int32_t{4000});
    enable();
    drive->set_velocity_set_value(1000);
    run(500ms);
    EXPECT_NEAR(drive->analog_output(1), 2.0, 0.1);
    EXPECT_NEAR(drive->analog_output(2), -1.5, 1e-9);
    EXPECT_NEAR(read<std::int16_t>(0x3170, 1), 2000, 100);
}

// 6.2.35: the host writes the general purpose outputs; polarity inverts the pin.
TEST_F(Escon2DriveIo, HostWritesGeneralPurposeOutputs) {
    write(0x60FE, 1, std::uint32_t{1U << 16});
    run(1ms);
    EXPECT_TRUE(drive->digital_output(1));
    EXPECT_FALSE(drive->digital_output(2));
    write(0x3150, 2, std::uint16_t{0x0002});
    run(1ms);
    EXPECT_TRUE(drive->digital_output(2)) << "inverted";
    EXPECT_EQ(read<std::uint32_t>(0x3152) & 0x0007'0000u, 0x0001'0000u);
}

} // namespace
} // namespace eposp::drives::escon2
