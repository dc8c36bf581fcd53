// The ESCON2's sensor errors from sensor faults injected into the plant (ESCON2 FW spec 7.1.22 -
// 7.1.24): each with its error code, error register, history entry and the "d" reaction
// (disabled at once, no quick stop ramp), and the supervision checking only the sensors that
// 0x3000 configures and supervises.
#include "escon2_drive_fixture.hpp"

#include <chrono>
#include <gtest/gtest.h>

namespace eposp::drives::escon2 {
namespace {

using namespace std::chrono_literals;

using namespace test;

constexpr std::uint8_t kSensorErrorRegister = 0b0010'0001; // table 110: 0x7380, 0x7388, 0x738A
constexpr std::int32_t kRpm = 1000;
constexpr int kPolePairs = 4;

// One fault each, the others absent.
plant::SensorFaults fault(void (*set)(plant::SensorFaults&)) {
    plant::SensorFaults faults;
    set(faults);
    return faults;
}
const plant::SensorFaults kBrokenEncoder = fault([](auto& f) { f.encoder_broken = true; });
const plant::SensorFaults kHallSupplyLost = fault([](auto& f) { f.hall_stuck_mask = 0b111; });
const plant::SensorFaults k512LineEncoder = fault([](auto& f) { f.encoder_pulses = 512; });

class Escon2SensorErrors : public test::Escon2DriveFixture {
protected:
    /// The reference axis with a brushed motor (the encoder alone, 6.2.13.1) or an EC motor
    /// (Hall sensors and encoder, the manual's default sensors 0x110).
    void start(plant::MotorKind motor) {
        Escon2DriveConfig config;
        config.axis.plant.motor.kind = motor;
        config.axis.plant.motor.pole_pairs = kPolePairs;
        Escon2DriveFixture::start(config);
    }

    /// I/O Velocity Mode at 1000 rpm, reached after 100 ms at the default 10'000 rpm/s.
    void run_at_speed() {
        controlword(0x06);
        controlword(0x0F);
        drive->set_velocity_set_value(kRpm);
        loop.run_for(200ms);
        ASSERT_EQ(state(), kOperationEnabled);
        ASSERT_EQ(read<std::uint8_t>(0x1003, 0), 0u) << "no error from working sensors";
    }

    /// Table 110 "d", the first error since start-up.
    void expect_disabled_with(std::uint16_t code) {
        Escon2DriveFixture::expect_disabled_with(code, kSensorErrorRegister);
        EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 1u);
    }

    /// Runs until the drive leaves Operation enabled (at most a second); the motor turns
    /// (4 × 500 qc each) from power-up to then.
    double turns_until_disabled() {
        for (int ms = 0; ms < 1000 && state() == kOperationEnabled; ++ms) {
            loop.run_for(1ms);
        }
        return static_cast<double>(drive->axis().position_actual()) / 2000;
    }

    /// Time passes, with a turn of direction, without any error.
    void expect_no_error() {
        drive->set_velocity_set_value(-kRpm);
        loop.run_for(1s);
        EXPECT_EQ(state(), kOperationEnabled);
        EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 0u);
        EXPECT_EQ(read<std::uint16_t>(0x603F), 0);
    }
};

// 7.1.22: the encoder, the main sensor (control structure 0x00020011), loses its signal. The
// fault reset clears the error; the repaired encoder raises nothing again.
TEST_F(Escon2SensorErrors, BrokenEncoderRaises7380MainSensorBreach) {
    start(plant::MotorKind::BrushedDc);
    run_at_speed();
    drive->inject_sensor_faults(kBrokenEncoder);
    expect_disabled_with(0x7380);
    drive->inject_sensor_faults({});
    controlword(0x80);
    loop.run_for(2ms);
    EXPECT_EQ(state(), kSwitchOnDisabled);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0);
    EXPECT_EQ(read<std::uint8_t>(0x1001), 0u);
}

// A fault reset while the encoder is still broken: the restarted supervision finds it again.
TEST_F(Escon2SensorErrors, ABreachStillThereAfterTheFaultResetIsFoundAgain) {
    start(plant::MotorKind::BrushedDc);
    run_at_speed();
    drive->inject_sensor_faults(kBrokenEncoder);
    expect_disabled_with(0x7380);
    controlword(0x80);
    loop.run_for(2ms);
    EXPECT_EQ(state(), kFault);
    EXPECT_EQ(read<std::uint16_t>(0x603F), 0x7380);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 2u) << "a new occurrence";
}

// 7.1.23: the Hall sensor supply lost while running: all three inputs low, an impossible
// combination; 0x301A sub 2 shows what the drive reads.
TEST_F(Escon2SensorErrors, HallSupplyLostRaises7388HallSensorSignalError) {
    start(plant::MotorKind::Ec);
    run_at_speed();
    drive->inject_sensor_faults(kHallSupplyLost);
    expect_disabled_with(0x7388);
    EXPECT_EQ(read<std::uint16_t>(0x301A, 2), 0u);
}

// 7.1.23 "incorrect wiring of Hall sensor supply voltage" from power-up: no Hall sensor edge
// within the first motor turn.
TEST_F(Escon2SensorErrors, DeadHallSensorsFromStartUpRaise7388WithinTheFirstTurn) {
    start(plant::MotorKind::Ec);
    drive->inject_sensor_faults(kHallSupplyLost);
    controlword(0x06);
    controlword(0x0F);
    drive->set_velocity_set_value(kRpm);
    const double turns = turns_until_disabled();
    expect_disabled_with(0x7388);
    EXPECT_GT(turns, 0.99);
    EXPECT_LT(turns, 1.2);
}

// 7.1.24 "wrong setting of encoder resolution": a 512-line encoder configured as 500 lines
// (0x3010 sub 1) drifts 2.4 % against the Hall sectors; past 30° electrical it is the error.
TEST_F(Escon2SensorErrors, WrongEncoderResolutionRaises738AHallAngleDetectionError) {
    start(plant::MotorKind::Ec);
    drive->inject_sensor_faults(k512LineEncoder);
    controlword(0x06);
    controlword(0x0F);
    drive->set_velocity_set_value(kRpm);
    const double turns = turns_until_disabled();
    expect_disabled_with(0x738A);
    // The drift, 2.4 % of 24 sectors a turn at four pole pairs, passes 30° beyond what the
    // readings allowed within about 1.3 turns.
    EXPECT_GT(turns, 1.0);
    EXPECT_LT(turns, 1.6);
}

// Working sensors raise nothing over many turns either way: the Hall angle check follows the
// sectors exactly.
TEST_F(Escon2SensorErrors, WorkingSensorsRaiseNothing) {
    start(plant::MotorKind::Ec);
    run_at_speed();
    expect_no_error();
}

// 6.2.13.1: a brushed DC motor has no Hall sensor, so dead Hall inputs are no error.
TEST_F(Escon2SensorErrors, NoHallErrorsWithoutHallSensors) {
    start(plant::MotorKind::BrushedDc);
    ASSERT_EQ(read<std::uint32_t>(0x3000, 1), 0x100u);
    drive->inject_sensor_faults(kHallSupplyLost);
    run_at_speed();
    expect_no_error();
}

// Hall sensors alone (sensor 1 the main sensor, 6.2.13.2): a broken encoder line is nobody's
// breach and no angle to compare.
TEST_F(Escon2SensorErrors, NoEncoderErrorsWithoutTheEncoder) {
    start(plant::MotorKind::Ec);
    write(0x3000, 2, std::uint32_t{0x0001'0011});
    write(0x3000, 3, std::uint32_t{0x10});
    write(0x3000, 1, std::uint32_t{0x010});
    drive->inject_sensor_faults(kBrokenEncoder);
    run_at_speed();
    expect_no_error();
}

// Table 52, bit 9: the commutation sensor supervision disabled, dead Hall sensors go unseen.
TEST_F(Escon2SensorErrors, HallErrorsGoUnseenWithTheCommutationSensorSupervisionDisabled) {
    start(plant::MotorKind::Ec);
    write(0x3000, 4, std::uint32_t{1U << 9});
    run_at_speed();
    drive->inject_sensor_faults(kHallSupplyLost);
    expect_no_error();
}

// Table 52, bit 8: the main sensor supervision disabled, a broken encoder is no breach. With
// only the encoder (a brushed motor) nothing is found; with Hall sensors the encoder's frozen
// angle leaves their sectors (7.1.24 "defective encoder").
TEST_F(Escon2SensorErrors, WithTheMainSensorSupervisionDisabledABrokenEncoderIsNoBreach) {
    start(plant::MotorKind::BrushedDc);
    write(0x3000, 4, std::uint32_t{1U << 8});
    run_at_speed();
    drive->inject_sensor_faults(kBrokenEncoder);
    expect_no_error();

    start(plant::MotorKind::Ec);
    write(0x3000, 4, std::uint32_t{1U << 8});
    run_at_speed();
    drive->inject_sensor_faults(kBrokenEncoder);
    loop.run_for(20ms);
    expect_disabled_with(0x738A);
}

} // namespace
} // namespace eposp::drives::escon2
