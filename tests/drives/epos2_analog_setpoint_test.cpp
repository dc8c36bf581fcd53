// The analog set values of the simulated EPOS2 (EPOS2 FW spec 6.1, 8.2.62 - 8.2.64, 8.2.81 -
// 8.2.83): an analog input voltage set from outside the drive commands Current, Velocity and
// Position Mode when 0x207B assigns the functionality to the input and 0x207D executes it;
// Analog Setpoint = Analog Input [V] · Scaling · 10^Notation Index + Offset (tables 8-109 -
// 8-111). All on the CAN-only bench.
#include "epos2_bus_fixture.hpp"

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::encode;

constexpr std::int8_t kPositionMode = -1;
constexpr std::int8_t kVelocityMode = -2;
constexpr std::int8_t kCurrentMode = -3;

struct ScalingCase {
    const char* name;
    std::int16_t scaling; ///< 0x2301 sub 1, mA/V
    std::int16_t offset;  ///< sub 2, mA
    std::int8_t notation; ///< sub 3
    std::int16_t millivolts;
    std::int16_t setpoint; ///< sub 4, mA
};

class AnalogCurrentScaling : public Epos2DriveOnBus,
                             public ::testing::WithParamInterface<ScalingCase> {};

// Table 8-109: the factor 10^0, 10^-1, 10^-2 on the scaling per volt; the offset added; negative
// voltages and scalings keep their signs.
TEST_P(AnalogCurrentScaling, SetpointIsVoltageTimesScalingTimesTenToTheNotationPlusOffset) {
    const ScalingCase& c = GetParam();
    write(0x207B, 1, encode(std::uint16_t{0})); // input 1: current setpoint
    write(0x2301, 1, encode(c.scaling));
    write(0x2301, 2, encode(c.offset));
    write(0x2301, 3, encode(c.notation));
    drive.set_analog_input(AnalogInput::Input1, c.millivolts);
    EXPECT_EQ(read<std::int16_t>(0x207C, 1), c.millivolts);
    EXPECT_EQ(read<std::int16_t>(0x2301, 4), c.setpoint);
}

INSTANTIATE_TEST_SUITE_P(
    Table8_109, AnalogCurrentScaling,
    ::testing::Values(ScalingCase{"NotationZero", 200, 50, 0, 1500, 350},
                      ScalingCase{"NotationMinusOne", 2000, 50, -1, 1500, 350},
                      ScalingCase{"NotationMinusTwo", 20000, 50, -2, 1500, 350},
                      ScalingCase{"NegativeScaling", -400, 0, 0, 2500, -1000},
                      ScalingCase{"NegativeVoltage", 1000, 100, 0, -300, -200},
                      ScalingCase{"RoundedToTheMilliampere", 1, 0, -2, 2550, 0}),
    [](const auto& test) { return std::string(test.param.name); });

// 5.13: executed (0x207D bit 0), the analog current set value commands Current Mode instead of
// 0x2030; 0x2031 shows it.
TEST_F(Epos2DriveOnBus, AnalogCurrentSetpointCommandsCurrentModeWhenExecuted) {
    write(0x207B, 2, encode(std::uint16_t{0})); // input 2: current setpoint
    write(0x2301, 1, encode(std::int16_t{200}));
    write(0x2301, 2, encode(std::int16_t{50}));
    write(0x6410, 4, encode(std::uint32_t{300})); // keep the free axis slow
    write(0x2030, 0, encode(std::int16_t{100}));
    drive.set_analog_input(AnalogInput::Input2, 1000);
    configure_and_enable(kCurrentMode);
    run_with_sync(5ms);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x2031, 0), 100) << "not executed: 0x2030";
    write(0x207D, 0, encode(std::uint16_t{0x0001}));
    run_with_sync(5ms);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x2031, 0), 250) << "1 V · 200 mA/V + 50 mA";
    drive.set_analog_input(AnalogInput::Input2, -1000);
    run_with_sync(5ms);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x2031, 0), -150);
}

// 5.11: executed (0x207D bit 1), the analog velocity set value commands Velocity Mode.
TEST_F(Epos2DriveOnBus, AnalogVelocitySetpointCommandsVelocityMode) {
    write(0x207B, 2, encode(std::uint16_t{1})); // input 2: velocity setpoint
    write(0x2302, 1, encode(std::int16_t{400}));
    write(0x2302, 2, encode(std::int32_t{-100}));
    write(0x207D, 0, encode(std::uint16_t{0x0002}));
    drive.set_analog_input(AnalogInput::Input2, 2000);
    configure_and_enable(kVelocityMode);
    run_with_sync(400ms);
    EXPECT_EQ(read<std::int32_t>(0x2302, 4), 700) << "2 V · 400 rpm/V − 100 rpm";
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x606B, 0), 700);
    EXPECT_NEAR(drive.objects().get_as<std::int32_t>(0x606C, 0), 700, 35);
}

// 5.6: executed (0x207D bit 2), the analog position set value commands Position Mode.
TEST_F(Epos2DriveOnBus, AnalogPositionSetpointCommandsPositionMode) {
    write(0x207B, 1, encode(std::uint16_t{2})); // input 1: position setpoint
    write(0x2303, 1, encode(std::int16_t{10000}));
    write(0x2303, 2, encode(std::int32_t{1000}));
    write(0x2303, 3, encode(std::int8_t{-2}));
    write(0x207D, 0, encode(std::uint16_t{0x0004}));
    write(0x60C5, 0, encode(std::uint32_t{10000}));
    drive.set_analog_input(AnalogInput::Input1, 2500);
    configure_and_enable(kPositionMode);
    run_with_sync(300ms);
    EXPECT_EQ(read<std::int32_t>(0x2303, 4), 1250) << "2.5 V · 10 000 · 10^-2 qc/V + 1000 qc";
    EXPECT_NEAR(drive.objects().get_as<std::int32_t>(0x6064, 0), 1250, 5);
}

// 8.2.64: an executed functionality that no input is configured for leaves the setting value
// in command.
TEST_F(Epos2DriveOnBus, ExecutedAnalogSetpointWithoutAnInputLeavesTheSettingValue) {
    write(0x207D, 0, encode(std::uint16_t{0x0002}));
    write(0x2302, 2, encode(std::int32_t{900}));
    write(0x206B, 0, encode(std::int32_t{300}));
    configure_and_enable(kVelocityMode);
    run_with_sync(300ms);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x606B, 0), 300);
}

class AnalogConfiguration : public Epos2DriveOnBus {};

// 8.2.62, 8.2.81 - 8.2.83: "Changes are only supported in Disable state": refused with 0x08000022
// (table 4-12, wrong device state) while the power stage is on, accepted again once it is off.
TEST_F(AnalogConfiguration, ChangesAreRefusedWhileThePowerStageIsOn) {
    configure_and_enable(kCurrentMode);
    EXPECT_EQ(try_write(0x2301, 1, encode(std::int16_t{100})), canopen::AbortCode::DeviceState);
    EXPECT_EQ(try_write(0x2303, 3, encode(std::int8_t{-1})), canopen::AbortCode::DeviceState);
    EXPECT_EQ(try_write(0x207B, 1, encode(std::uint16_t{0})), canopen::AbortCode::DeviceState);
    EXPECT_EQ(read<std::int16_t>(0x2301, 1), 0);
    controlword(kShutdown);
    run_with_sync(10ms);
    EXPECT_EQ(try_write(0x2301, 1, encode(std::int16_t{100})), canopen::AbortCode::None);
    EXPECT_EQ(try_write(0x207B, 1, encode(std::uint16_t{0})), canopen::AbortCode::None);
}

// 8.2.62: "A functionality can only be assigned to one of the two analog inputs at the same
// time": the other input's functionality is refused (0x06040043, general parameter
// incompatibility).
TEST_F(AnalogConfiguration, OneFunctionalityIsAssignedToOneInputOnly) {
    write(0x207B, 1, encode(std::uint16_t{1}));
    EXPECT_EQ(try_write(0x207B, 2, encode(std::uint16_t{1})),
              canopen::AbortCode::ParameterIncompatibility);
    EXPECT_EQ(read<std::uint16_t>(0x207B, 2), 14U) << "unchanged: general purpose B";
    EXPECT_EQ(try_write(0x207B, 2, encode(std::uint16_t{0})), canopen::AbortCode::None);
}

} // namespace
} // namespace eposp::drives::epos2
