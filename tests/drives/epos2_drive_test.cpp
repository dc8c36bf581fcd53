// A simulated EPOS2 driven purely through CAN frames, the way a CANopen master configures and
// moves a real one: NMT, SDO writes of the mode and profile, controlword and target by RPDO,
// statusword and position by TPDO on SYNC, EMCY on errors. All in virtual time.
#include "epos2_bus_fixture.hpp"
#include "eposp/test/epos2_network.hpp"

#include <set>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::AbortCode;
using canopen::encode;

// 5.3: an absolute move of 20000 qc at 1000 rpm, 10000 rpm/s on a 500-pulse encoder
// (2000 qc/turn): v = 33 333 qc/s, a = 333 333 qc/s², so 0.1 s ramps and 0.5 s cruise.
TEST_F(Epos2DriveOnBus, ProfilePositionMoveByPdoReachesTargetAtTheTrapezoidTime) {
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint | kChangeImmediately, 20000);
    const double commanded = now();
    run_with_sync(5ms);
    const Tpdo acknowledged = tpdos.back();
    EXPECT_NE(acknowledged.statusword & 0x1000, 0) << "set-point acknowledge";
    EXPECT_EQ(acknowledged.statusword & 0x0400, 0) << "target reached cleared by the new move";
    controlword_and_target(kEnableOperation, 20000);
    run_with_sync(900ms);

    const double v = 1000.0 * 2000 / 60;
    const double a = 10000.0 * 2000 / 60;
    const double move_time = v / a + 20000 / v;
    const std::optional<Tpdo> reached = first_tpdo_with(0x0400, commanded + 0.01);
    ASSERT_TRUE(reached.has_value());
    EXPECT_NEAR(reached->time - commanded, move_time, 0.002); // one control period + one SYNC
    EXPECT_NEAR(tpdos.back().position, 20000, 5);
    EXPECT_EQ(tpdos.back().statusword & 0x1000, 0) << "acknowledge follows bit 4 back";
    EXPECT_EQ(read<std::int32_t>(0x6064, 0), tpdos.back().position);
}

// 5.3.1, figure 5-9: the same move with sin² ramps (0x6086 = 1). The profile acceleration is
// the peak, so each ramp lasts 2·v/a and covers v²/a: the move takes 2·v/a + d/v = 0.8 s.
TEST_F(Epos2DriveOnBus, SinSquaredMoveByPdoReachesTargetAtTheClosedFormTime) {
    write(0x6086, 0, encode(std::int16_t{1}));
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint | kChangeImmediately, 20000);
    const double commanded = now();
    run_with_sync(5ms);
    controlword_and_target(kEnableOperation, 20000);
    run_with_sync(1000ms);

    const double v = 1000.0 * 2000 / 60;
    const double a = 10000.0 * 2000 / 60;
    const double move_time = 2 * v / a + 20000 / v;
    const std::optional<Tpdo> reached = first_tpdo_with(0x0400, commanded + 0.01);
    ASSERT_TRUE(reached.has_value());
    EXPECT_NEAR(reached->time - commanded, move_time, 0.002); // one control period + one SYNC
    EXPECT_NEAR(tpdos.back().position, 20000, 5);
}

// 8.2.85: a relative target adds to the last target.
TEST_F(Epos2DriveOnBus, RelativeMoveAddsToThePosition) {
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint | 0x0040, -3000);
    run_with_sync(5ms);
    controlword_and_target(kEnableOperation | 0x0040, -3000);
    run_with_sync(500ms);
    EXPECT_NEAR(tpdos.back().position, -3000, 5);
    EXPECT_NE(tpdos.back().statusword & 0x0400, 0);
}

// 5.10: Profile Velocity reaches its target velocity and says so.
TEST_F(Epos2DriveOnBus, ProfileVelocityReachesTheTargetVelocity) {
    configure_and_enable(3);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), 3);
    EXPECT_NE(tpdos.back().statusword & 0x1000, 0) << "speed is equal 0 at rest";
    write(0x60FF, 0, encode(std::int32_t{500}));
    run_with_sync(300ms);
    // Velocity is measured in quadcounts per millisecond (8.2.48): 30 rpm steps at 2000 qc/turn.
    EXPECT_NEAR(read<std::int32_t>(0x606C, 0), 500, 35);
    EXPECT_NE(tpdos.back().statusword & 0x0400, 0) << "target reached";
    EXPECT_EQ(tpdos.back().statusword & 0x1000, 0) << "speed no longer 0";
}

// 8.2.44 - 8.2.48, 8.2.51, 8.2.71, 8.2.97: the measured values a master reads, at a steady
// 500 rpm (16 667 qc/s at 2000 qc/turn). The load's friction takes about 45 mA. Instant values
// are compared at one instant (the dictionary without a bus round trip).
TEST_F(Epos2DriveOnBus, MeasuredValuesFollowTheMotion) {
    configure_and_enable(3);
    write(0x60FF, 0, encode(std::int32_t{500}));
    run_with_sync(1000ms);
    EXPECT_NEAR(read<std::int32_t>(0x6069, 0), 16667, 1000); // qc/s, measured per ms
    EXPECT_NEAR(read<std::int32_t>(0x2028, 0), 500, 10);     // rpm, 5 Hz low-pass
    EXPECT_NEAR(read<std::int16_t>(0x2027, 0), 45, 30);      // mA, 50 Hz low-pass
    EXPECT_EQ(read<std::uint16_t>(0x2022, 0), 0U) << "a DC motor has no hall sensors";
    const auto index_count = static_cast<std::int32_t>(read<std::uint32_t>(0x2021, 0));
    EXPECT_GT(index_count, 0);
    EXPECT_LE(index_count % 2000, 2) << "the index sits at a whole turn";

    canopen::ObjectDictionary& od = drive.objects();
    EXPECT_EQ(static_cast<std::int32_t>(od.get_as<std::uint32_t>(0x2020, 0)),
              od.get_as<std::int32_t>(0x6064, 0))
        << "the raw counter is the position without a homing offset";
    EXPECT_EQ(od.get_as<std::int32_t>(0x2031, 0),
              std::lround(drive.axis().current_demand() * 1000));
    EXPECT_EQ(od.get_as<std::int16_t>(0x20F4, 0),
              od.get_as<std::int32_t>(0x6062, 0) - od.get_as<std::int32_t>(0x6064, 0));
}

// 8.2.90: a value table 8-118 does not list is refused as out of range (table 4-12).
TEST_F(Epos2DriveOnBus, ModesTable8_118DoesNotListAreRefused) {
    std::optional<AbortCode> result;
    client.download(kNode, 0x6060, 0, encode(std::int8_t{2}), // CiA 402 velocity mode
                    [&result](AbortCode code) { result = code; });
    loop.run_for(20ms);
    EXPECT_EQ(result, AbortCode::InvalidValue);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), 1);
}

// 5.4.3.10: method 35 makes the actual position the home position, by SDO only.
TEST_F(Epos2DriveOnBus, HomingOnActualPositionBySdo) {
    configure_and_enable(6);
    write(0x6098, 0, encode(std::int8_t{35}));
    write(0x2081, 0, encode(std::int32_t{1234}));
    write(0x6040, 0, encode(std::uint16_t{kEnableOperation | kNewSetpoint}));
    run_with_sync(20ms);
    const std::uint16_t statusword = read<std::uint16_t>(0x6041, 0);
    EXPECT_NE(statusword & 0x1000, 0) << "homing attained";
    EXPECT_NE(statusword & 0x0400, 0) << "target reached";
    EXPECT_NE(statusword & 0x8000, 0) << "referenced";
    EXPECT_NEAR(read<std::int32_t>(0x6064, 0), 1234, 2);
}

class Epos2DriveWithHomeSwitch : public Epos2DriveOnBus {
protected:
    static plant::AxisParameters axis_with_switch() {
        plant::AxisParameters axis = plant::test::tuned_axis();
        axis.switches.home = 3000;
        return axis;
    }
    Epos2DriveWithHomeSwitch() : Epos2DriveOnBus(axis_with_switch()) {}
};

// 5.4.3.7: method 23, falling edge of the home switch on the positive side, found by SDO.
TEST_F(Epos2DriveWithHomeSwitch, HomingOnTheHomeSwitchEdge) {
    configure_and_enable(6);
    write(0x6098, 0, encode(std::int8_t{23}));
    write(0x6099, 1, encode(std::uint32_t{200}));
    write(0x6099, 2, encode(std::uint32_t{20}));
    write(0x609A, 0, encode(std::uint32_t{5000}));
    write(0x6040, 0, encode(std::uint16_t{kEnableOperation | kNewSetpoint}));
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1) & 0x0004, 0) << "home switch not pressed yet";
    run_with_sync(3000ms);
    const std::uint16_t statusword = read<std::uint16_t>(0x6041, 0);
    EXPECT_NE(statusword & 0x1000, 0) << "homing attained";
    EXPECT_NE(statusword & 0x8000, 0) << "referenced";
    EXPECT_NEAR(read<std::int32_t>(0x6064, 0), 0, 3);
}

class Epos2DriveWithBlockedLoad : public Epos2DriveOnBus {
protected:
    static plant::AxisParameters blocked_axis() {
        plant::AxisParameters axis = plant::test::tuned_axis();
        axis.plant.load.coulomb_friction = 100; // far beyond the motor's torque: it cannot turn
        return axis;
    }
    Epos2DriveWithBlockedLoad() : Epos2DriveOnBus(blocked_axis()) {}
};

// 4.2.22, table 4-11: following error 0x8611 with error register bit 5 (motion error), in the
// history, the fault reaction ending in Fault; fault reset clears it.
TEST_F(Epos2DriveWithBlockedLoad, FollowingErrorRaisesEmcyAndFaults) {
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 20000);
    run_with_sync(1000ms);
    ASSERT_FALSE(emcys.empty());
    const std::vector<std::uint8_t>& emcy = emcys.front();
    ASSERT_EQ(emcy.size(), 8U);
    EXPECT_EQ(emcy[0], 0x11);
    EXPECT_EQ(emcy[1], 0x86);
    EXPECT_NE(emcy[2] & 0x20, 0) << "motion error";
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x8611U);
    EXPECT_NE(read<std::uint8_t>(0x1001, 0) & 0x20, 0);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kFault);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);

    controlword(kFaultReset);
    run_with_sync(10ms);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kSwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
    ASSERT_GE(emcys.size(), 2U);
    EXPECT_EQ(emcys.back()[0], 0x00);
    EXPECT_EQ(emcys.back()[1], 0x00);
}

// 4.2 / 8.2.84: a CAN error the node raises (RPDO 1 too short: 0x8210) is an "a" error whose
// default reaction (0x6007 = 3, quickstop) ends in Fault.
TEST_F(Epos2DriveOnBus, PdoLengthErrorTriggersTheCommunicationFaultReaction) {
    configure_and_enable(1);
    master->send(can::Frame::data_frame(kRpdo1Id, {0x0F}));
    run_with_sync(100ms);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x8210U);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
}

// 4.2, table 4-11 / 8.2.14: the master's heartbeat, consumed with 0x1016, stops: EMCY 0x8130
// with the communication bit 0x10 in the error register, and the "a" reaction ends in Fault.
TEST_F(Epos2DriveOnBus, MissingHeartbeatOfTheMasterRaises8130AndFaults) {
    constexpr std::uint8_t kMaster = 0x7F;
    write(0x1016, 1, encode(std::uint32_t{kMaster} << 16 | 50)); // within 50 ms
    configure_and_enable(1);
    master->send(can::Frame::data_frame(0x700 + kMaster, {0x05}));
    run_with_sync(40ms);
    EXPECT_TRUE(emcys.empty()) << "the heartbeat came within its time";
    run_with_sync(100ms);
    ASSERT_FALSE(emcys.empty());
    // Communication only: table 4-11 gives 0x8130 the register value 0001 0000b.
    EXPECT_EQ(emcys.front(), (std::vector<std::uint8_t>{0x30, 0x81, 0x10, 0, 0, 0, 0, 0}));
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0x10);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x8130U);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
}

// 8.2.105 / 5.3.2.1: a target beyond the software position limit is refused with 0xFF09.
TEST_F(Epos2DriveOnBus, TargetBeyondSoftwareLimitRaisesFF09) {
    write(0x607D, 2, encode(std::int32_t{10000}));
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 20000);
    run_with_sync(100ms); // the quickstop ends after the standstill time (0x2101 sub 2: 50 ms)
    ASSERT_FALSE(emcys.empty());
    EXPECT_EQ(emcys.front()[0], 0x09);
    EXPECT_EQ(emcys.front()[1], 0xFF);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
    EXPECT_NEAR(tpdos.back().position, 0, 5);
}

// 8.2.105: an endless movement (no target to check) is stopped by the actual position crossing
// the limit: 0xFF09, fault.
TEST_F(Epos2DriveOnBus, EndlessMoveBeyondSoftwareLimitRaisesFF09) {
    write(0x607D, 2, encode(std::int32_t{10000}));
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint | 0x8000, 1);
    run_with_sync(1000ms);
    ASSERT_FALSE(emcys.empty());
    EXPECT_EQ(emcys.front()[0], 0x09);
    EXPECT_EQ(emcys.front()[1], 0xFF);
    EXPECT_NE(emcys.front()[2] & 0x80, 0) << "manufacturer specific error";
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
    EXPECT_GE(tpdos.back().position, 10000);
}

// 8.2.89: a fault reaction option code written by the master applies: -1 signals only.
TEST_F(Epos2DriveWithBlockedLoad, FaultReactionOptionCodeMinusOneOnlyWarns) {
    write(0x605E, 0, encode(std::int16_t{-1}));
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 20000);
    run_with_sync(500ms);
    ASSERT_FALSE(emcys.empty());
    EXPECT_EQ(emcys.front()[1], 0x86);
    EXPECT_EQ(drive.state(), motion::DriveState::OperationEnable);
    EXPECT_NE(tpdos.back().statusword & 0x0080, 0) << "warning";
    EXPECT_NE(tpdos.back().statusword & 0x2000, 0) << "following error";
}

class Epos2DriveWithLimitSwitch : public Epos2DriveOnBus {
protected:
    static plant::AxisParameters axis_with_limit() {
        plant::AxisParameters axis = plant::test::tuned_axis();
        axis.switches.positive_limit = 5000;
        return axis;
    }
    Epos2DriveWithLimitSwitch() : Epos2DriveOnBus(axis_with_limit()) {}
};

// 8.2.57 / 4.2.28: the positive limit switch, executed once its bit of 0x2071 sub 4 is set,
// raises 0xFF07 (error register bit 7) and faults.
TEST_F(Epos2DriveWithLimitSwitch, ExecutedPositiveLimitSwitchRaisesFF07) {
    write(0x2071, 4, encode(std::uint16_t{0x000B})); // limit switches and position marker
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 20000);
    run_with_sync(600ms);
    ASSERT_FALSE(emcys.empty());
    EXPECT_EQ(emcys.front()[0], 0x07);
    EXPECT_EQ(emcys.front()[1], 0xFF);
    EXPECT_NE(emcys.front()[2] & 0x80, 0);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
    EXPECT_NE(read<std::uint16_t>(0x2071, 1) & 0x0002, 0) << "the switch shows in the state";
}

// Table 8-89: with the default execution mask (0x0008) the switch is only displayed.
TEST_F(Epos2DriveWithLimitSwitch, LimitSwitchNotInTheExecutionMaskIsOnlyDisplayed) {
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 8000);
    run_with_sync(600ms);
    EXPECT_TRUE(emcys.empty());
    EXPECT_NEAR(tpdos.back().position, 8000, 5);
    EXPECT_NE(read<std::uint16_t>(0x2071, 1) & 0x0002, 0);
}

TEST(Epos2Network, EveryDriveBootsWithItsOwnNodeId) {
    core::EventLoop loop;
    eposp::test::Epos2Network network =
        eposp::test::make_epos2_network(loop, 3, drive_config(plant::test::tuned_axis()), 5);
    std::vector<std::uint32_t> boot_ups;
    auto master = network.bus->connect("master");
    master->on_receive([&boot_ups](const can::Frame& frame) { boot_ups.push_back(frame.id); });
    // Reset node to all: each answers with its boot-up (CiA 301 7.2.8.3.2).
    master->send(can::Frame::data_frame(canopen::kNmtCanId, {0x81, 0x00}));
    loop.run_for(50ms);
    const std::set<std::uint32_t> nodes_booted(boot_ups.begin(), boot_ups.end());
    EXPECT_EQ(nodes_booted, (std::set<std::uint32_t>{0x705, 0x706, 0x707}));
}

} // namespace
} // namespace eposp::drives::epos2
