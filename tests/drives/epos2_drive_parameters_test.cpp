// Parameters a master writes while the drive runs configure the plant from then on (EPOS2 FW spec
// 8.2.74, 8.2.125 - 8.2.130), and restore is refused outside "Power Disable" and pre-operational
// (8.2.9).
#include "epos2_bus_fixture.hpp"

#include <numbers>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::AbortCode;
using canopen::encode;

// 8.2.125 - 8.2.127: every gain of the three parameter sets reaches the controllers.
TEST_F(Epos2DriveOnBus, ControlParameterSetsWrittenLaterReachTheControllers) {
    configure_and_enable(1);
    write(0x60F6, 1, encode(std::int16_t{900}));
    write(0x60F6, 2, encode(std::int16_t{9000}));
    write(0x60F9, 1, encode(std::int16_t{400}));
    write(0x60F9, 2, encode(std::int16_t{2000}));
    write(0x60F9, 4, encode(std::uint16_t{10}));
    write(0x60F9, 5, encode(std::uint16_t{20}));
    write(0x60FB, 1, encode(std::int16_t{2000}));
    write(0x60FB, 2, encode(std::int16_t{4000}));
    write(0x60FB, 3, encode(std::int16_t{400}));
    write(0x60FB, 4, encode(std::uint16_t{30}));
    write(0x60FB, 5, encode(std::uint16_t{40}));
    const plant::ServoGains& gains = drive.axis().parameters().gains;
    EXPECT_DOUBLE_EQ(gains.current.kp, 0.9);
    EXPECT_DOUBLE_EQ(gains.current.ki, 9000);
    EXPECT_DOUBLE_EQ(gains.velocity.kp, 0.04);
    EXPECT_DOUBLE_EQ(gains.velocity.ki, 2);
    EXPECT_DOUBLE_EQ(gains.velocity.velocity_feed_forward, 10e-4);
    EXPECT_DOUBLE_EQ(gains.velocity.acceleration_feed_forward, 20e-6);
    EXPECT_DOUBLE_EQ(gains.position.kp, 2);
    EXPECT_DOUBLE_EQ(gains.position.ki, 4);
    EXPECT_DOUBLE_EQ(gains.position.kd, 0.04);
    EXPECT_DOUBLE_EQ(gains.position.velocity_feed_forward, 30e-4);
    EXPECT_DOUBLE_EQ(gains.position.acceleration_feed_forward, 40e-6);
}

// Without position gains and feed-forward the controller produces no current: the move the
// default gains make (ProfilePositionMoveByPdo…) no longer happens.
TEST_F(Epos2DriveOnBus, PositionGainsWrittenZeroStopTheAxisFollowing) {
    write(0x6065, 0, encode(std::uint32_t{0xFFFF'FFFF})); // following error off
    configure_and_enable(1);
    for (std::uint8_t sub = 1; sub <= 5; ++sub) {
        write(0x60FB, sub, sub <= 3 ? encode(std::int16_t{0}) : encode(std::uint16_t{0}));
    }
    controlword_and_target(kEnableOperation | kNewSetpoint, 20000);
    run_with_sync(800ms);
    EXPECT_EQ(drive.axis().current_actual(), 0.0);
    EXPECT_NEAR(tpdos.back().position, 0, 2);
}

// 8.2.74: the encoder's pulses, written while disabled, count the same shaft at the new
// resolution: a move of 4000 qc is one turn with 1000 pulses. The position is no longer
// referenced.
TEST_F(Epos2DriveOnBus, EncoderPulsesWrittenLaterChangeTheQuadcountsPerTurn) {
    write(0x6098, 0, encode(std::int8_t{35}));
    configure_and_enable(6);
    write(0x6040, 0, encode(std::uint16_t{kEnableOperation | kNewSetpoint}));
    run_with_sync(20ms);
    ASSERT_NE(read<std::uint16_t>(0x6041, 0) & 0x8000, 0) << "referenced";

    controlword(kShutdown);
    run_with_sync(10ms);
    write(0x2210, 1, encode(std::uint32_t{1000}));
    EXPECT_EQ(drive.axis().parameters().encoder_pulses, 1000);
    EXPECT_EQ(read<std::uint16_t>(0x6041, 0) & 0x8000, 0) << "reference lost";
    write(0x6060, 0, encode(std::int8_t{1}));
    const double start_angle = drive.axis().motor().state().angle;
    const std::int32_t start = read<std::int32_t>(0x6064, 0);
    for (const std::uint16_t word : {kSwitchOn, kEnableOperation}) {
        controlword(word);
        run_with_sync(10ms);
    }
    controlword_and_target(kEnableOperation | kNewSetpoint | 0x0040, 4000); // relative
    run_with_sync(600ms);
    EXPECT_NEAR(read<std::int32_t>(0x6064, 0) - start, 4000, 5);
    EXPECT_NEAR(drive.axis().motor().state().angle - start_angle, 2 * std::numbers::pi, 0.02);
}

// 8.2.129 / 8.2.130: motor type, pole pairs and the output current limit configure the plant.
TEST_F(Epos2DriveOnBus, MotorTypeAndMotorDataWrittenLaterConfigureThePlant) {
    EXPECT_EQ(read<std::uint16_t>(0x6402, 0), 1U) << "the reference motor is brushed DC";
    EXPECT_EQ(read<std::uint16_t>(0x6410, 2), 3000U) << "its 3 A current limit";
    EXPECT_EQ(drive.axis().hall_sensors(), 0) << "a DC motor has no hall sensors";
    write(0x6402, 0, encode(std::uint16_t{10})); // sinusoidal PM BL motor
    write(0x6410, 3, encode(std::uint8_t{4}));
    write(0x6410, 2, encode(std::uint16_t{2500}));
    const plant::AxisParameters& parameters = drive.axis().parameters();
    EXPECT_EQ(parameters.plant.motor.kind, plant::MotorKind::Ec);
    EXPECT_EQ(parameters.plant.motor.pole_pairs, 4);
    EXPECT_DOUBLE_EQ(parameters.gains.current_limit, 2.5);
    EXPECT_NE(drive.axis().hall_sensors(), 0);
}

std::optional<AbortCode> restore(Epos2DriveOnBus& bench) {
    std::optional<AbortCode> result;
    bench.client.download(kNode, 0x1011, 1, encode(std::uint32_t{0x6461'6F6C}), // "load"
                          [&result](AbortCode code) { result = code; });
    bench.loop.run_for(20ms);
    return result;
}

// 8.2.9: restore only in "Power Disable" and pre-operational.
TEST_F(Epos2DriveOnBus, RestoreIsRefusedOutsidePowerDisableAndPreOperational) {
    EXPECT_EQ(restore(*this), AbortCode::None) << "switch on disabled, pre-operational";
    write(0x6040, 0, encode(kShutdown));
    write(0x6040, 0, encode(kSwitchOn));
    EXPECT_EQ(restore(*this), AbortCode::DeviceState) << "switched on: power enabled";
    write(0x6040, 0, encode(std::uint16_t{0}));
    nmt(canopen::NmtCommand::Start);
    EXPECT_EQ(restore(*this), AbortCode::DeviceState) << "operational";
    nmt(canopen::NmtCommand::EnterPreOperational);
    EXPECT_EQ(restore(*this), AbortCode::None);
}

// 8.2.42: 0x200A shows the bit rate in use as a code of table 8-81; with 0x2001 at its default
// 9 ("automatic bit rate detection") that is the bus's, 500 kbit/s here (code 2).
TEST(Epos2DriveBitRate, CanBitrateDisplayShowsTheBitRateInUse) {
    core::EventLoop loop;
    can::VirtualBus bus{loop, {.bitrate = 500'000}};
    const std::unique_ptr<can::VirtualPort> port = bus.connect("epos2");
    const std::unique_ptr<can::VirtualPort> listener = bus.connect("master");
    Epos2DriveConfig config = drive_config(plant::test::tuned_axis());
    config.dictionary.bit_rate = 500'000;
    Epos2Drive drive(loop, *port, std::move(config));
    drive.start();
    loop.run_for(10ms);
    canopen::Bytes shown;
    ASSERT_EQ(drive.objects().read(0x200A, 0, shown), AbortCode::None);
    EXPECT_EQ(canopen::decode<std::uint16_t>(shown), 2U);
    EXPECT_EQ(drive.objects().get_as<std::uint16_t>(0x2001, 0), 9U);
}

// 8.2.68: after a homing, 0x2082 shows how far the home found lies from the previous Home
// Position (in the coordinates before); the position is then the Home Position. Homing on the
// actual position (method 35) 1000 qc from the first home shows 1000.
TEST_F(Epos2DriveOnBus, HomePositionDisplacementShowsTheDistanceFromThePreviousHome) {
    write(0x6098, 0, encode(std::int8_t{35}));
    configure_and_enable(6);
    const auto home = [this] {
        controlword(kEnableOperation | kNewSetpoint);
        run_with_sync(20ms);
        controlword(kEnableOperation);
        run_with_sync(5ms);
    };
    home();
    EXPECT_NEAR(read<std::int32_t>(0x2082, 0), 0, 2) << "the axis was where the counter began";
    const std::int32_t first = read<std::int32_t>(0x6064, 0);
    write(0x6060, 0, encode(std::int8_t{1}));
    controlword_and_target(kEnableOperation | kNewSetpoint | 0x0040, 1000); // relative
    run_with_sync(300ms);
    controlword(kEnableOperation); // bit 4 low, for the next homing's rising edge
    const std::int32_t moved = read<std::int32_t>(0x6064, 0) - first;
    ASSERT_NEAR(moved, 1000, 5);
    write(0x6060, 0, encode(std::int8_t{6}));
    run_with_sync(5ms);
    home();
    EXPECT_NEAR(read<std::int32_t>(0x2082, 0), first + moved, 2);
    EXPECT_NEAR(read<std::int32_t>(0x6064, 0), 0, 2);
}

} // namespace
} // namespace eposp::drives::epos2
