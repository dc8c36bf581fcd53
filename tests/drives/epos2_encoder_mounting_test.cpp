// Where the machine's encoder sits and which way it counts, and what the EPOS2 makes of it
// (EPOS2 FW spec 8.2.74, 8.2.79, tables 8-103, 8-104, 8-119; 4.2.37): with a gear configured the
// encoder is on the gear's output and the drive's positions and velocities are the output's; an
// encoder mounted the other way round is read right with 0x2210 sub 4 and runs away without it.
// The reference axis has 500 pulses: 2000 qc per turn of the encoder's shaft. All on the CAN-only
// bench, in virtual time.
#include "epos2_bus_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::AbortCode;
using canopen::encode;

constexpr std::int8_t kProfilePosition = 1;
constexpr std::int8_t kProfileVelocity = 3;
constexpr std::int8_t kCurrentMode = -3;
constexpr double kCountsPerTurn = 2000;
constexpr std::uint16_t kTargetReached = 0x0400;
constexpr std::uint16_t kMainSensorDirectionError = 0xFF11; // 4.2.37, register 0010 0000b
constexpr std::uint16_t kFollowingError = 0x8611;           // 4.2.22, register 0010 0000b

double rpm(double radians_per_second) {
    return radians_per_second * 60 / (2 * std::numbers::pi);
}

// A 3:1 gearhead with the encoder on its output (8.2.74).
plant::AxisParameters geared_axis() {
    plant::AxisParameters axis = plant::test::tuned_axis();
    axis.plant.gearhead.ratio = 3;
    axis.encoder_mounting.on_gear_output = true;
    return axis;
}

class GearedAxis : public Epos2DriveOnBus {
public:
    GearedAxis() : Epos2DriveOnBus(geared_axis()) {}

    /// 0x2230: 3 / 1, as a master configures the gear of a real drive (in Disable state).
    void configure_gear() {
        write(0x2230, 1, encode(std::uint32_t{3}));
        write(0x2230, 2, encode(std::uint16_t{1}));
    }
    double motor_turns() const {
        return drive.axis().motor().state().angle / (2 * std::numbers::pi);
    }
    double motor_rpm() const { return rpm(drive.axis().motor().state().speed); }
};

// 5.3 on the output: N output turns are N × 4 × 500 counts while the motor turns 3N times, at the
// trapezoid time of the output's profile (1000 rpm, 10 000 rpm/s: 0.1 s ramps + d / v).
TEST_F(GearedAxis, OutputTurnsAreTheCountsWhileTheMotorTurnsGearRatioTimesAsOften) {
    configure_gear();
    configure_and_enable(kProfilePosition);
    constexpr int kOutputTurns = 5;
    const auto target = static_cast<std::int32_t>(kOutputTurns * kCountsPerTurn);
    controlword_and_target(kEnableOperation | kNewSetpoint | kChangeImmediately, target);
    const double commanded = now();
    run_with_sync(5ms);
    controlword_and_target(kEnableOperation, target);
    run_with_sync(800ms);

    const double v = 1000 * kCountsPerTurn / 60;
    const double a = 10000 * kCountsPerTurn / 60;
    const std::optional<Tpdo> reached = first_tpdo_with(kTargetReached, commanded + 0.01);
    ASSERT_TRUE(reached.has_value());
    EXPECT_NEAR(reached->time - commanded, v / a + target / v, 0.002);
    EXPECT_NEAR(read<std::int32_t>(0x6064, 0), target, 2);
    // Within the reading's two counts and the count it rounds down to: three of the motor each.
    EXPECT_NEAR(motor_turns(), 3 * kOutputTurns, 3 * 3 / kCountsPerTurn);
    EXPECT_EQ(drive.axis().parameters().encoder_reading.gear_ratio, 3);
    EXPECT_TRUE(emcys.empty());
}

// 5.10 on the output: 0x606C is the output's speed, the motor turns three times as fast.
TEST_F(GearedAxis, VelocityIsTheOutputsAndTheMotorTurnsGearRatioTimesAsFast) {
    configure_gear();
    configure_and_enable(kProfileVelocity);
    write(0x60FF, 0, encode(std::int32_t{500}));
    run_with_sync(500ms);
    // 1 qc per millisecond is 30 rpm at 2000 qc per turn (8.2.48).
    EXPECT_NEAR(read<std::int32_t>(0x606C, 0), 500, 35);
    EXPECT_NEAR(read<std::int32_t>(0x2028, 0), 500, 10); // averaged
    EXPECT_NEAR(motor_rpm(), 3 * 500, 3 * 10);
    // The index once per output turn: the sensor supervision finds the resolution configured.
    EXPECT_TRUE(emcys.empty());
}

// 8.2.130 sub 4 is the motor's speed: through the gear it caps the output at a third of it.
TEST_F(GearedAxis, CurrentModeCapsTheMotorAtMaximalMotorSpeedThroughTheGear) {
    configure_gear();
    write(0x6410, 4, encode(std::uint32_t{1500}));
    configure_and_enable(kCurrentMode);
    write(0x2030, 0, encode(std::int16_t{300}));
    run_with_sync(1000ms);
    EXPECT_NEAR(read<std::int32_t>(0x606C, 0), 500, 35);
    EXPECT_NEAR(motor_rpm(), 1500, 3 * 20);
}

// Without 0x2230 the drive takes the encoder for the motor's: positions stay the output's counts,
// but the loop sees a third of the motor's angle (its gains a third as stiff) and Maximal Motor
// Speed caps the output instead of the motor.
TEST_F(GearedAxis, WithoutAGearConfiguredMaximalMotorSpeedCapsTheOutput) {
    write(0x6410, 4, encode(std::uint32_t{500}));
    configure_and_enable(kCurrentMode);
    write(0x2030, 0, encode(std::int16_t{300}));
    run_with_sync(1000ms);
    EXPECT_NEAR(read<std::int32_t>(0x606C, 0), 500, 35);
    EXPECT_NEAR(motor_rpm(), 1500, 3 * 20);
    EXPECT_EQ(drive.axis().parameters().encoder_reading.gear_ratio, 1);
}

// 8.2.79: "Can only be changed in Disable state".
TEST_F(GearedAxis, GearIsRefusedWhileThePowerStageIsOn) {
    configure_and_enable(kProfilePosition);
    EXPECT_EQ(try_write(0x2230, 1, encode(std::uint32_t{3})), AbortCode::DeviceState);
}

// A brushless motor commutated by its hall sensors (0x6402 = 11: table 8-103 permits it a gear).
plant::AxisParameters geared_ec_axis() {
    plant::AxisParameters axis = geared_axis();
    axis.plant.motor.kind = plant::MotorKind::Ec;
    return axis;
}

class GearedEcAxis : public Epos2DriveOnBus {
public:
    GearedEcAxis() : Epos2DriveOnBus(geared_ec_axis()) {}
};

// 4.2.26, "No Hall sensor 3 edge found within first motor turn", through the gear: with hall
// sensor 3 stuck, 0xFF04 comes once the output's encoder has counted one motor turn (2000 / 3
// counts), not a turn of the output.
TEST_F(GearedEcAxis, HallSensorNotFoundWithinTheFirstMotorTurnThroughTheGear) {
    write(0x6402, 0, encode(std::uint16_t{11}));
    write(0x2230, 1, encode(std::uint32_t{3}));
    plant::SensorFaults hall_sensor_3_stuck;
    hall_sensor_3_stuck.hall_stuck_mask = 0b100;
    drive.inject_sensor_faults(hall_sensor_3_stuck);
    configure_and_enable(kProfilePosition);
    controlword_and_target(kEnableOperation | kNewSetpoint | kChangeImmediately, 20000);
    run_with_sync(300ms);
    expect_error(*this, 0xFF04, 0b1000'0000);
    const auto at_error = std::find_if(tpdos.begin(), tpdos.end(), [this](const Tpdo& tpdo) {
        return tpdo.time >= emcy_times.front();
    });
    ASSERT_NE(at_error, tpdos.end());
    EXPECT_GT(at_error->position, kCountsPerTurn / 3);
    EXPECT_LT(at_error->position, kCountsPerTurn / 3 + 100);
}

// An encoder mounted the other way round: it counts down while the motor turns CCW.
plant::AxisParameters reversed_encoder_axis() {
    plant::AxisParameters axis = plant::test::tuned_axis();
    axis.encoder_mounting.counts_against_motor = true;
    return axis;
}

class ReversedEncoder : public Epos2DriveOnBus {
public:
    ReversedEncoder() : Epos2DriveOnBus(reversed_encoder_axis()) {}

    /// A profile position move to `target` (the move of ProfilePositionMoveByPdo…).
    void move_to(std::int32_t target, std::chrono::milliseconds duration) {
        controlword_and_target(kEnableOperation | kNewSetpoint | kChangeImmediately, target);
        run_with_sync(5ms);
        controlword_and_target(kEnableOperation, target);
        run_with_sync(duration);
    }
};

// Table 8-104: the machine's encoder makes sub 4 bit 0 the default, and read inverted it moves the
// axis as the reference axis moves: 20 000 qc at the trapezoid time, the motor turning CCW.
TEST_F(ReversedEncoder, InvertedPolarityFromTheMachineReadsItRight) {
    EXPECT_EQ(read<std::uint16_t>(0x2210, 4), 1U);
    configure_and_enable(kProfilePosition);
    const double commanded = now();
    move_to(20000, 900ms);
    const double v = 1000 * kCountsPerTurn / 60;
    const double a = 10000 * kCountsPerTurn / 60;
    const std::optional<Tpdo> reached = first_tpdo_with(kTargetReached, commanded + 0.01);
    ASSERT_TRUE(reached.has_value());
    EXPECT_NEAR(reached->time - commanded, v / a + 20000 / v, 0.002);
    EXPECT_NEAR(tpdos.back().position, 20000, 5);
    EXPECT_NEAR(drive.axis().motor().state().angle / (2 * std::numbers::pi), 10,
                5 / kCountsPerTurn);
    EXPECT_TRUE(emcys.empty());
}

// 4.2.37: with sub 4 not matching the mounting, the position loop pushes the motor the way that
// takes the reading away from the demand; the software sensor supervision finds the encoder
// counting against the motor a quarter turn (500 qc) on and disables the drive, long before the
// following error (2000 qc) would.
TEST_F(ReversedEncoder, MismatchedPolarityRunsAwayIntoTheMainSensorDirectionError) {
    write(0x2210, 4, encode(std::uint16_t{0}));
    configure_and_enable(kProfilePosition);
    move_to(20000, 200ms);
    expect_error(*this, kMainSensorDirectionError, 0b0010'0000);
    const std::optional<Tpdo> fault = first_tpdo_with(kFault, 0);
    ASSERT_TRUE(fault.has_value());
    EXPECT_LT(fault->position, -500) << "the reading ran away from the target";
    EXPECT_GT(fault->position, -2000) << "before the following error";
    EXPECT_GT(drive.axis().motor().state().angle, 0) << "the motor turned towards the target";
}

// 8.2.41 bit 0 disables the software supervision: the runaway goes on until the following error
// (0x6065 = 2000 qc) raises 0x8611. Its fault reaction (0x605E: the quickstop ramp) runs on the
// same runaway loop and cannot bring the axis to rest: the standstill timeout (0x2101 sub 3,
// 1000 ms) ends it in Fault.
TEST_F(ReversedEncoder, MismatchWithoutSoftwareSupervisionEndsInTheFollowingError) {
    write(0x2210, 4, encode(std::uint16_t{0}));
    write(0x2008, 0, encode(std::uint16_t{0x0001}));
    configure_and_enable(kProfilePosition);
    move_to(20000, 200ms);
    ASSERT_FALSE(emcys.empty());
    EXPECT_EQ(emcy_bytes(emcys.front())[0] | emcy_bytes(emcys.front())[1] << 8, kFollowingError);
    EXPECT_EQ(drive.state(), motion::DriveState::FaultReactionActiveEnabled);
    run_with_sync(1000ms);
    expect_error(*this, kFollowingError, 0b0010'0000);
}

// 8.2.74: "Can only be changed in Disable state"; written there, it acts from then on.
TEST_F(ReversedEncoder, PolarityIsRefusedWhileThePowerStageIsOn) {
    configure_and_enable(kProfilePosition);
    EXPECT_EQ(try_write(0x2210, 4, encode(std::uint16_t{0})), AbortCode::DeviceState);
    EXPECT_TRUE(drive.axis().parameters().encoder_reading.inverted);
}

} // namespace
} // namespace eposp::drives::epos2
