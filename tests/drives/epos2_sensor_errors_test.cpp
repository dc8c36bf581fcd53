// The sensor errors of table 4-11 from sensor faults injected into the plant (EPOS2 FW spec
// 4.2.23 - 4.2.26, 4.2.31): each with its EMCY, error register, the "d" reaction (disabled at
// once, no ramp) and the position reset when it is cleared.
#include "epos2_bus_fixture.hpp"

#include <algorithm>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::encode;

constexpr std::uint8_t kSensorErrorRegister = 0x80; // table 4-11: 1000 0000b
constexpr std::uint16_t kReferencedBit = 1U << 15;

// One fault each, the others absent.
plant::SensorFaults fault(void (*set)(plant::SensorFaults&)) {
    plant::SensorFaults faults;
    set(faults);
    return faults;
}
const plant::SensorFaults kBrokenEncoder = fault([](auto& f) { f.encoder_broken = true; });
const plant::SensorFaults kMissingIndex = fault([](auto& f) { f.index_missing = true; });
const plant::SensorFaults k512LineEncoder = fault([](auto& f) { f.encoder_pulses = 512; });
const plant::SensorFaults kHallSensor3StuckLow = fault([](auto& f) { f.hall_stuck_mask = 0b100; });
const plant::SensorFaults kHallSupplyLost = fault([](auto& f) { f.hall_stuck_mask = 0b111; });

class Epos2SensorErrors : public Epos2DriveOnBus {
public:
    /// A relative move of ten turns (20000 qc at 500 pulses) at 1000 rpm: about 0.6 s.
    void start_long_move() {
        controlword_and_target(kEnableOperation | kNewSetpoint | 0x0040, 20000);
    }

    /// "d": a secure movement is no longer possible, the drive is disabled at once: the TPDO
    /// two control periods after the EMCY shows Fault, not the quickstop ramp of "f" or "a"
    /// (100 ms from 1000 rpm at 10000 rpm/s).
    void expect_disabled_at_once() {
        ASSERT_FALSE(emcy_times.empty());
        const double emcy = emcy_times.front();
        const auto after = std::find_if(tpdos.begin(), tpdos.end(), [emcy](const Tpdo& tpdo) {
            return tpdo.time > emcy + 0.0025;
        });
        ASSERT_NE(after, tpdos.end());
        EXPECT_EQ(after->statusword & kStateMask, kFault);
        EXPECT_EQ(drive.axis().current_actual(), 0.0) << "power stage off";
    }

    /// Homing on the actual position (method 35) references it, then the long move starts.
    void start_referenced_long_move() {
        write(0x6098, 0, encode(std::int8_t{35}));
        configure_and_enable(6);
        controlword(kEnableOperation | 0x0010);
        run_with_sync(20ms);
        controlword(kEnableOperation);
        write(0x6060, 0, encode(std::int8_t{1}));
        start_long_move();
    }

    void use_ec_motor() {
        write(0x6402, 0, encode(std::uint16_t{10})); // sinusoidal PM BL motor (table 8-125)
    }
};

// 4.2.31: a broken encoder line, seen by the hardware supervision.
TEST_F(Epos2SensorErrors, BrokenEncoderRaisesFF0APositionSensorBreach) {
    configure_and_enable(1);
    start_long_move();
    run_with_sync(100ms);
    ASSERT_TRUE(emcys.empty());
    drive.inject_sensor_faults(kBrokenEncoder);
    run_with_sync(10ms);
    expect_error(*this, 0xFF0A, kSensorErrorRegister);
    expect_disabled_at_once();
}

// 8.2.41, table 8-83 bit 1: "Disable sensor supervision by hardware".
TEST_F(Epos2SensorErrors, BrokenEncoderGoesUnseenWithTheHardwareSupervisionDisabled) {
    write(0x2008, 0, encode(std::uint16_t{0x0002}));
    configure_and_enable(1);
    drive.inject_sensor_faults(kBrokenEncoder);
    run_with_sync(50ms);
    EXPECT_TRUE(emcys.empty());
    EXPECT_EQ(drive.state(), motion::DriveState::OperationEnable);
}

// 4.2.24: "Encoder index signal was not found within two turns at start-up".
TEST_F(Epos2SensorErrors, MissingIndexRaisesFF02AfterTwoTurns) {
    drive.inject_sensor_faults(kMissingIndex);
    configure_and_enable(1);
    start_long_move();
    run_with_sync(700ms);
    expect_error(*this, 0xFF02, kSensorErrorRegister);
    expect_disabled_at_once();
    // Two turns of 2000 qc, not before.
    const auto at_error = std::find_if(tpdos.begin(), tpdos.end(), [this](const Tpdo& tpdo) {
        return tpdo.time >= emcy_times.front();
    });
    ASSERT_NE(at_error, tpdos.end());
    EXPECT_GT(at_error->position, 4000);
    EXPECT_LT(at_error->position, 4000 + 100);
}

// An encoder with index that works raises nothing over many turns (the same move).
TEST_F(Epos2SensorErrors, AWorkingEncoderRaisesNothing) {
    use_ec_motor();
    configure_and_enable(1);
    start_long_move();
    run_with_sync(700ms);
    EXPECT_TRUE(emcys.empty());
    EXPECT_NEAR(tpdos.back().position, 20000, 10);
}

// 4.2.25: "Encoder pulses counted between the first two index pulses does not fit to
// resolution": a 512-line encoder configured as 500 lines counts 2048 qc from index to index.
TEST_F(Epos2SensorErrors, WrongResolutionRaisesFF03AtTheSecondIndex) {
    drive.inject_sensor_faults(k512LineEncoder);
    configure_and_enable(1);
    start_long_move();
    run_with_sync(700ms);
    expect_error(*this, 0xFF03, kSensorErrorRegister);
    expect_disabled_at_once();
}

// 4.2.26: "No Hall sensor 3 edge found within first motor turn": hall sensor 3 stuck low.
TEST_F(Epos2SensorErrors, StuckHallSensor3RaisesFF04WithinTheFirstTurn) {
    use_ec_motor();
    drive.inject_sensor_faults(kHallSensor3StuckLow);
    configure_and_enable(1);
    start_long_move();
    run_with_sync(700ms);
    expect_error(*this, 0xFF04, kSensorErrorRegister);
    expect_disabled_at_once();
    const auto at_error = std::find_if(tpdos.begin(), tpdos.end(), [this](const Tpdo& tpdo) {
        return tpdo.time >= emcy_times.front();
    });
    ASSERT_NE(at_error, tpdos.end());
    EXPECT_GT(at_error->position, 2000);
    EXPECT_LT(at_error->position, 2000 + 100);
}

// 4.2.23: "an impossible signal combination" (the hall supply lost: all three low) once the
// hall sensors were found; 0x2022 shows what the drive reads.
TEST_F(Epos2SensorErrors, HallSupplyLostRaisesFF01) {
    use_ec_motor();
    configure_and_enable(1);
    start_long_move();
    run_with_sync(100ms);
    ASSERT_TRUE(emcys.empty());
    drive.inject_sensor_faults(kHallSupplyLost);
    run_with_sync(10ms);
    expect_error(*this, 0xFF01, kSensorErrorRegister);
    expect_disabled_at_once();
    EXPECT_EQ(read<std::uint16_t>(0x2022, 0), 0U);
}

// Table 4-11 "Position Reset": clearing the error resets the actual position, which is no longer
// referenced; the sensors start up again (a fault still there is found again).
TEST_F(Epos2SensorErrors, ClearingASensorErrorResetsTheActualPosition) {
    start_referenced_long_move();
    run_with_sync(100ms);
    ASSERT_NE(tpdos.back().statusword & kReferencedBit, 0);
    ASSERT_GT(tpdos.back().position, 1000);
    drive.inject_sensor_faults(kBrokenEncoder);
    run_with_sync(1000ms); // the motor coasts to rest
    ASSERT_EQ(drive.state(), motion::DriveState::Fault);
    ASSERT_EQ(drive.axis().velocity_actual(), 0.0);
    drive.inject_sensor_faults({});
    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::int32_t>(0x6064, 0), 0);
    EXPECT_EQ(tpdos.back().statusword & kReferencedBit, 0);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kSwitchOnDisabled);
}

// 4.2.29: "Angle difference measured between encoder and Hall sensors is too high due to ...
// wrong setting of encoder resolution": a 512-line encoder configured as 500 lines (no index, so
// that 0xFF03 does not find it first) drifts against the Hall sectors by 2.4 % of an electrical
// turn per electrical turn until it is more than 30 degrees off. "f": the 0x605E quickstop ramp,
// then Fault; clearing it resets the actual position (table 4-11).
TEST_F(Epos2SensorErrors, WrongEncoderResolutionRaisesFF08HallAngleDetection) {
    use_ec_motor();
    write(0x2210, 2, encode(std::uint16_t{2})); // encoder without index (table 8-102)
    configure_and_enable(1);
    drive.inject_sensor_faults(k512LineEncoder);
    start_long_move();
    run_with_sync(700ms);
    expect_emcy(*this, 0xFF08, kSensorErrorRegister);
    const double emcy = emcy_times.front();
    const auto ramp = std::find_if(tpdos.begin(), tpdos.end(),
                                   [emcy](const Tpdo& tpdo) { return tpdo.time > emcy + 0.0025; });
    ASSERT_NE(ramp, tpdos.end());
    EXPECT_EQ(ramp->statusword & 0x004F, 0x000F) << "Fault Reaction Active: the ramp runs";
    run_with_sync(300ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);

    drive.inject_sensor_faults({});
    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::int32_t>(0x6064, 0), 0) << "position reset";
}

// The default machine's Hall sensors and encoder agree: an EC motor moving ten turns raises no
// hall angle error (nor any other).
TEST_F(Epos2SensorErrors, HallSensorsAndEncoderOfTheMachineAgree) {
    use_ec_motor();
    configure_and_enable(1);
    start_long_move();
    run_with_sync(1000ms);
    EXPECT_TRUE(emcys.empty());
    EXPECT_EQ(drive.state(), motion::DriveState::OperationEnable);
}

// 8.2.74: sinus commutation on encoder 1 needs at least 16 pulses per pole pair. 500 pulses and
// 32 pole pairs (512) are found at the Enable Operation command: 0x7320 Position Sensor Error,
// "d" with position reset (table 4-11); 31 pole pairs (496) enable.
TEST_F(Epos2SensorErrors, TooFewPulsesPerPolePairRaise7320AtEnableOperation) {
    use_ec_motor();
    write(0x6410, 3, encode(std::uint8_t{32}));
    nmt(canopen::NmtCommand::Start);
    for (const std::uint16_t word : {kShutdown, kSwitchOn}) {
        controlword(word);
        run_with_sync(10ms);
    }
    ASSERT_TRUE(emcys.empty()) << "found at Enable Operation only";
    controlword(kEnableOperation);
    run_with_sync(10ms);
    expect_error(*this, 0x7320, 0x20);
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);

    write(0x6410, 3, encode(std::uint8_t{31}));
    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    for (const std::uint16_t word : {kShutdown, kSwitchOn, kEnableOperation}) {
        controlword(word);
        run_with_sync(10ms);
    }
    EXPECT_EQ(drive.state(), motion::DriveState::OperationEnable);
    EXPECT_EQ(emcys.size(), 2u) << "the error and its reset only";
}

// 8.2.74: another main sensor type clears the Position Actual Value and the referenced bit;
// another pulse number only the referenced bit ("the absolute position could be corrupt").
TEST_F(Epos2SensorErrors, AnotherMainSensorTypeClearsTheActualPosition) {
    start_referenced_long_move();
    run_with_sync(1000ms);
    ASSERT_NE(tpdos.back().statusword & kReferencedBit, 0);
    const auto moved = read<std::int32_t>(0x6064, 0);
    ASSERT_GT(moved, 10000);
    controlword(0); // Disable Voltage: changes only in Disable state
    run_with_sync(10ms);
    write(0x2210, 1, encode(std::uint32_t{500}));
    run_with_sync(2ms);
    EXPECT_EQ(read<std::int32_t>(0x6064, 0), moved);
    EXPECT_EQ(tpdos.back().statusword & kReferencedBit, 0);
    write(0x2210, 2, encode(std::uint16_t{2}));
    run_with_sync(2ms);
    EXPECT_EQ(read<std::int32_t>(0x6064, 0), 0);
}

} // namespace
} // namespace eposp::drives::epos2
