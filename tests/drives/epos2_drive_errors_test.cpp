// The errors the simulated machine can cause besides motion errors (EPOS2 FW spec 4.2, table
// 4-11): each with its EMCY frame, error register 0x1001, error history 0x1003, fault reaction
// and recovery.
#include "epos2_bus_fixture.hpp"

#include <algorithm>
#include <cmath>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::encode;

class Epos2DriveErrors : public Epos2DriveOnBus {
public:
    using Epos2DriveOnBus::Epos2DriveOnBus;
};

// 4.2.5: "Power supply voltage too high"; "d": disabled at once; a fault reset is refused until
// the supply is back in range.
TEST_F(Epos2DriveErrors, OvervoltageRaises3210AndDisables) {
    configure_and_enable(1);
    drive.set_supply_voltage(30);
    run_with_sync(5ms);
    expect_error(*this, 0x3210, 0x04);
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);

    controlword(kFaultReset);
    run_with_sync(5ms);
    controlword(0);
    run_with_sync(5ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault) << "supply still too high";

    drive.set_supply_voltage(24);
    controlword(kFaultReset);
    run_with_sync(5ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
    EXPECT_EQ(emcy_bytes(emcys.back()), (EmcyBytes{}));
}

// 4.2.6: "Supply voltage is too low for operation", also while the power stage is off.
TEST_F(Epos2DriveErrors, UndervoltageRaises3220EvenWhenDisabled) {
    drive.set_supply_voltage(8);
    nmt(canopen::NmtCommand::Start);
    run_with_sync(5ms);
    expect_error(*this, 0x3220, 0x04);

    drive.set_supply_voltage(12);
    controlword(kFaultReset);
    run_with_sync(5ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
}

class Epos2DriveOvercurrent : public Epos2DriveErrors {
protected:
    // A load the motor cannot turn, and a power stage that trips at 5 A.
    static plant::AxisParameters stalled_axis() {
        plant::AxisParameters axis = plant::test::tuned_axis();
        axis.plant.load.coulomb_friction = 100;
        axis.plant.power_stage.overcurrent = 5;
        return axis;
    }

public:
    Epos2DriveOvercurrent() : Epos2DriveErrors(stalled_axis()) {}
};

// 4.2.3: "Controller gains too high": the output current limit 0x6410 sub 2, raised by SDO while
// the axis runs, lets the position controller of a stalled motor drive its current past the
// power stage's limit. The following error is off so that it does not stop the drive first.
TEST_F(Epos2DriveOvercurrent, OutputCurrentLimitWrittenLaterLetsTheCurrentTrip2310) {
    write(0x6065, 0, encode(std::uint32_t{0xFFFF'FFFF}));
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 20000);
    run_with_sync(300ms);
    EXPECT_TRUE(emcys.empty()) << "3 A, the default limit, stays below the 5 A trip";
    EXPECT_NEAR(drive.axis().current_actual(), 3.0, 0.1);

    write(0x6410, 2, encode(std::uint16_t{8000}));
    run_with_sync(50ms);
    expect_error(*this, 0x2310, 0x02);
    EXPECT_EQ(drive.axis().current_actual(), 0.0) << "power stage off";
}

// 4.2.18: the CAN controller goes bus-off: an "a" error (0x6007 = 3 by default: quickstop, then
// Fault). The controller cannot send while bus-off; the EMCY leaves once it has recovered.
TEST_F(Epos2DriveErrors, BusOffRaises81FDWithTheAbortConnectionReaction) {
    configure_and_enable(1);
    device->force_error_state(can::ErrorState::BusOff);
    EXPECT_EQ(device->error_state(), can::ErrorState::BusOff);
    run_with_sync(100ms); // automatic recovery after 128 × 11 recessive bits
    EXPECT_EQ(device->error_state(), can::ErrorState::Active);
    expect_error(*this, 0x81FD, 0x10);
}

// Table 3-4 under the mask of bits 0-3 and 6: Fault Reaction Active.
constexpr std::uint16_t kFaultReactionMask = 0x004F;
constexpr std::uint16_t kFaultReactionActive = 0x000F;

// The "a" reaction with 0x6007 = 3 (the default, 8.2.84): a quickstop of the axis moving at
// 1000 rpm, Fault Reaction Active for the ramp, then Fault.
void expect_quickstop_reaction(Epos2DriveOnBus& bench) {
    ASSERT_FALSE(bench.emcy_times.empty());
    const double emcy = bench.emcy_times.front();
    const auto ramp = std::find_if(bench.tpdos.begin(), bench.tpdos.end(),
                                   [emcy](const Tpdo& t) { return t.time > emcy + 0.01; });
    ASSERT_NE(ramp, bench.tpdos.end());
    EXPECT_EQ(ramp->statusword & kFaultReactionMask, kFaultReactionActive);
    bench.run_with_sync(200ms);
    EXPECT_EQ(bench.drive.state(), motion::DriveState::Fault);
}

void start_long_move(Epos2DriveOnBus& bench) {
    bench.controlword_and_target(kEnableOperation | kNewSetpoint | 0x0040, 20000);
    bench.run_with_sync(100ms);
    ASSERT_TRUE(bench.emcys.empty());
}

// 4.2.15: the CAN controller goes error-passive (it still sends: the EMCY leaves at once).
TEST_F(Epos2DriveErrors, ErrorPassiveRaises8120WithTheAbortConnectionReaction) {
    configure_and_enable(1);
    start_long_move(*this);
    device->force_error_state(can::ErrorState::Passive);
    run_with_sync(20ms);
    expect_emcy(*this, 0x8120, 0x10);
    expect_quickstop_reaction(*this);
}

// 4.2.19: "One of the CAN receive queues had an overrun": the drive's controller holds the
// frames it has not taken (its virtual port paused) beyond its receive queue (64 frames).
TEST_F(Epos2DriveErrors, ReceiveQueueOverflowRaises81FE) {
    configure_and_enable(1);
    start_long_move(*this);
    device->pause_receive(true);
    for (int burst = 0; burst < 10; ++burst) {
        for (int frame = 0; frame < 10; ++frame) {
            master->send(can::Frame::data_frame(0x7F0, {0}));
        }
        loop.run_for(2ms);
    }
    device->pause_receive(false);
    run_with_sync(5ms);
    expect_emcy(*this, 0x81FE, 0x10);
    expect_quickstop_reaction(*this);
}

// 4.2.20: "One of the CAN transmit queues had an overrun ... heartbeat producer enabled" while
// a higher-priority babbler holds the bus: the 65th heartbeat finds the transmit queue (64
// frames) full. The EMCY meets the same full queue and is lost like any frame sent then; the
// register, the history and the 0x6007 reaction show the error.
TEST_F(Epos2DriveErrors, TransmitQueueOverflowRaises81FF) {
    configure_and_enable(1);
    start_long_move(*this);
    write(0x1017, 0, encode(std::uint16_t{1})); // heartbeat every ms
    master->babble(can::Frame::data_frame(0x001, {0}));
    loop.run_for(100ms);
    master->stop_babbling();
    run_with_sync(20ms);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0x10);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 1U);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x81FFU);
    run_with_sync(200ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault) << "0x6007 = 3: quickstop, then Fault";
}

// 4.2.20, 4.1: the EMCY of 0x81FF meets the transmit queue it reports full; it waits and leaves
// once the queue has room, so that the master learns of the lost frames.
TEST_F(Epos2DriveErrors, TransmitQueueOverflowEmcyLeavesOnceTheQueueHasRoom) {
    configure_and_enable(1);
    start_long_move(*this);
    write(0x1017, 0, encode(std::uint16_t{1})); // heartbeat every ms
    master->babble(can::Frame::data_frame(0x001, {0}));
    loop.run_for(100ms);
    ASSERT_TRUE(emcys.empty()) << "nothing of the drive passes the babbling idiot";
    master->stop_babbling();
    const double stopped = now();
    run_with_sync(20ms);
    ASSERT_EQ(emcys.size(), 1U);
    EXPECT_GE(emcy_times.front(), stopped);
    expect_emcy(*this, 0x81FF, 0x10);
}

// 4.2.7: "Temperature at device's power stage too high". The power stage off dissipates
// nothing, so its temperature follows the ambient as the first-order body of the defaults
// (PowerStageThermal: τ = 60 s, limit 100 °C): 110 − 85·e^(−t/τ) passes 100 °C at
// τ·ln(85 / 10) = 128.40 s. "d": Fault; a fault reset only once it has cooled below the limit.
TEST_F(Epos2DriveErrors, HotCabinetRaises4210WhenThePowerStagePassesItsLimit) {
    nmt(canopen::NmtCommand::Start); // the controlword by RPDO
    const double start = now();
    drive.set_ambient_temperature(110);
    const double crossing = 60 * std::log(85.0 / 10.0);
    loop.run_for(
        std::chrono::duration_cast<core::Duration>(std::chrono::duration<double>(crossing - 0.01)));
    EXPECT_TRUE(emcys.empty());
    loop.run_for(20ms);
    ASSERT_EQ(emcys.size(), 1U);
    EXPECT_NEAR(emcy_times.front() - start, crossing, 0.002);
    expect_error(*this, 0x4210, 0x08);

    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault) << "still above 100 °C";
    drive.set_ambient_temperature(25);
    run_with_sync(100ms);
    ASSERT_LT(drive.power_stage_temperature(), 100);
    controlword(0);
    run_with_sync(2ms);
    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
}

// 4.2.17: "Device has received a bad transmit PDO request (valid COB-ID without RTR bit set)":
// a data frame on the COB-ID of the drive's TPDO 3. A remote request there is no collision
// (0x1802 sub 1 bit 30 refuses it: nothing happens). "a": 0x6007 = 3, quickstop, then Fault;
// a fault reset recovers.
TEST_F(Epos2DriveErrors, DataFrameOnAnOwnTpdoCobIdRaises8150) {
    configure_and_enable(1);
    start_long_move(*this);
    master->send(can::Frame::remote_frame(kTpdo3Id, 6));
    run_with_sync(10ms);
    ASSERT_TRUE(emcys.empty()) << "a remote request is no collision";

    master->send(can::Frame::data_frame(kTpdo3Id, {1, 2, 3, 4, 5, 6}));
    run_with_sync(20ms);
    expect_emcy(*this, 0x8150, 0x10);
    expect_quickstop_reaction(*this);

    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
    EXPECT_EQ(emcy_bytes(emcys.back()), (EmcyBytes{}));
}

// 4.2.36: "Control function not possible due to controller gains of zero": the power stage
// comes on (Measure Init, table 3-3) holding the position with the position loop, whose P gain
// 0x60FB sub 1 is zero. Fault; a fault reset with the gain back recovers.
TEST_F(Epos2DriveErrors, ZeroPositionGainRaisesFF10WhenThePowerStageComesOn) {
    write(0x60FB, 1, encode(std::int16_t{0}));
    nmt(canopen::NmtCommand::Start);
    for (const std::uint16_t word : {kShutdown, kSwitchOn}) {
        controlword(word);
        run_with_sync(10ms);
    }
    ASSERT_TRUE(emcys.empty()) << "the power stage is still off";
    controlword(kEnableOperation);
    run_with_sync(200ms);
    expect_error(*this, 0xFF10, 0x20);
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);

    write(0x60FB, 1, encode(std::int16_t{500}));
    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
}

// 4.2.36: a zero velocity P gain (0x60F9 sub 1) does not hinder the position loop of Profile
// Position Mode; entering Velocity Mode, whose loop it is, raises 0xFF10 with the "f" reaction
// (0x605E = 2 by default: quickstop ramp, then Fault).
TEST_F(Epos2DriveErrors, ZeroVelocityGainRaisesFF10OnEnteringVelocityMode) {
    write(0x60F9, 1, encode(std::int16_t{0}));
    configure_and_enable(1);
    start_long_move(*this);
    write(0x6060, 0, encode(std::int8_t{-2}));
    run_with_sync(5ms);
    expect_emcy(*this, 0xFF10, 0x20);
    run_with_sync(200ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
}

// 4.2.4: "The power stage driver reports an error: short circuit of the motor winding". The
// short shows only once the power stage drives the motor (Measure Init); "d": Fault, power stage
// off. A fault reset is allowed (the spec names no condition); enabling trips again while the
// short lasts, and runs once it is repaired.
TEST_F(Epos2DriveErrors, WindingShortRaises2320WhenThePowerStageDrivesTheMotor) {
    drive.short_motor_winding(true);
    nmt(canopen::NmtCommand::Start);
    const auto enable = [this] {
        for (const std::uint16_t word : {kShutdown, kSwitchOn, kEnableOperation}) {
            controlword(word);
            run_with_sync(10ms);
        }
    };
    enable();
    expect_error(*this, 0x2320, 0x02);
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);

    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
    enable();
    EXPECT_EQ(drive.state(), motion::DriveState::Fault) << "still shorted";
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 2U) << "a second event";

    drive.short_motor_winding(false);
    controlword(kFaultReset);
    run_with_sync(10ms);
    enable();
    EXPECT_EQ(drive.state(), motion::DriveState::OperationEnable);
}

// 4.2.8: "Overload on internally generated 5 V supply at Hall sensor connector or encoder
// connector": the drive reports the cause, 0x5113 ("d"), not what the unpowered sensors would
// make its sensor supervision find (no 0xFF0A); the Hall inputs read low (0x2022). A fault reset
// is refused until the supply is repaired.
TEST_F(Epos2DriveErrors, OverloadedSensorSupplyRaises5113Alone) {
    configure_and_enable(1);
    start_long_move(*this);
    plant::SensorFaults overloaded;
    overloaded.supply_overloaded = true;
    drive.inject_sensor_faults(overloaded);
    run_with_sync(20ms);
    expect_error(*this, 0x5113, 0x04);
    EXPECT_EQ(emcys.size(), 1U) << "no sensor error besides";
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);
    EXPECT_EQ(read<std::uint16_t>(0x2022, 0), 0);

    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault) << "the 5 V supply is still overloaded";

    drive.inject_sensor_faults({});
    controlword(0);
    run_with_sync(2ms);
    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
    EXPECT_EQ(emcy_bytes(emcys.back()), (EmcyBytes{}));
}

// 4.2.11: "Target Position too high with Profile Velocity too low": the simulation's planner
// holds a move of at most (2^31 - 1) ms at the profile velocity (docs/epos2.md). At 1 rpm and
// 4 × 0x2210 sub 1 counts per turn the longest move is 2147483.647 s × counts/s: a move of that
// many counts (rounded down) is planned, one count more from the same target raises 0x6320 ("f":
// quickstop, then Fault); a fault reset recovers.
TEST_F(Epos2DriveErrors, MoveLongerThanThePlannerHoldsRaises6320) {
    configure_and_enable(1);
    write(0x6081, 0, encode(std::uint32_t{1})); // rpm
    const double counts_per_second = 4.0 * read<std::uint32_t>(0x2210, 1) / 60.0;
    const auto longest = static_cast<std::int32_t>(std::floor(2'147'483.647 * counts_per_second));
    controlword_and_target(kEnableOperation | kNewSetpoint, longest);
    run_with_sync(10ms);
    controlword_and_target(kEnableOperation, longest);
    run_with_sync(10ms);
    ASSERT_TRUE(emcys.empty()) << "the longest move is planned";

    // Change immediately, from the target `longest` back to -1: one count too far.
    controlword_and_target(kEnableOperation | kNewSetpoint | kChangeImmediately, -1);
    run_with_sync(10ms);
    expect_emcy(*this, 0x6320, 0x20);
    run_with_sync(200ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);

    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
}

// 4.2.32: "Device has not enough free resources to process new target value": the system load
// set from outside above 1 (motion::SystemLoad). The drive runs on while no target value comes;
// the next target written (RPDO 3: controlword and target position) raises 0xFF0B ("d":
// disabled at once). A fault reset recovers (the spec names no condition).
TEST_F(Epos2DriveErrors, TargetValueWrittenWhileOverloadedRaisesFF0B) {
    configure_and_enable(1);
    drive.set_system_load(1.0);
    controlword_and_target(kEnableOperation | kNewSetpoint, 1000);
    run_with_sync(20ms);
    ASSERT_TRUE(emcys.empty()) << "a load of 1 is all the processor has, no more";
    controlword_and_target(kEnableOperation, 1000);
    run_with_sync(10ms);
    drive.set_system_load(1.2);
    run_with_sync(20ms);
    ASSERT_TRUE(emcys.empty()) << "no new target value";

    controlword_and_target(kEnableOperation, 2000);
    run_with_sync(10ms);
    expect_error(*this, 0xFF0B, 0x20);
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);

    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
}

} // namespace
} // namespace eposp::drives::epos2
