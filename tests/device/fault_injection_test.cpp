// Fault injection into the EPOS P's simulated network (device::FaultInjector, docs/eposp.md,
// "Fault injection"): each fault with what a PLC programmer sees of it (the error history, the
// axis' PLCopen state and error), and every wrong target refused with a reason.

#include "compile_program.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/error_entry.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <optional>
#include <string>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using drives::epos2::LimitSwitch;

constexpr std::string_view kNetwork = R"(
sync_period: 1ms
boot_time: 500ms
slaves:
  - {node: 1, port: internal, axis: 0, heartbeat: 100ms}
  - {node: 2, axis: 1, heartbeat: 100ms}
  - {node: 3, kind: external, axis: 2, mandatory: false}
)";

constexpr std::string_view kProgram = R"ST(
PROGRAM Main
VAR
  Axis0 : AXIS_REF := (AxisNo := 0);
  Axis1 : AXIS_REF := (AxisNo := 1);
  Power0, Power1 : MC_Power;
  Move0, Move1 : MC_MoveAbsolute;
  State0, State1 : MC_ReadAxisState;
  Error1 : MC_ReadAxisError;
  Reset1 : MC_Reset;
  Go, DoReset : BOOL;
END_VAR
Power0(Axis := Axis0, Enable := TRUE);
Power1(Axis := Axis1, Enable := TRUE);
Move0(Axis := Axis0, Execute := Go, Position := 200000, Velocity := 3000,
      Acceleration := 10000, Deceleration := 10000);
Move1(Axis := Axis1, Execute := Go, Position := -120000, Velocity := 3000,
      Acceleration := 10000, Deceleration := 10000);
State0(Axis := Axis0, Enable := TRUE);
State1(Axis := Axis1, Enable := TRUE);
Error1(Axis := Axis1, Enable := TRUE);
Reset1(Axis := Axis1, Execute := DoReset);
END_PROGRAM
CONFIGURATION Cell
  RESOURCE EposP ON EPOS_P
    TASK Motion (INTERVAL := T#1ms, PRIORITY := 1);
    PROGRAM Main WITH Motion : Main;
  END_RESOURCE
END_CONFIGURATION
)ST";

constexpr const char* kErrorStop = "6";
constexpr const char* kStandstill = "1";

class FaultInjection : public testing::Test {
protected:
    void SetUp() override {
        const auto network = parse_network_file(kNetwork, "net.yaml");
        ASSERT_TRUE(network) << network.error();
        device.add_network(*network);
        ASSERT_FALSE(device.plc().load(compile_program(std::string(kProgram))));
        ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
        device.loop().run_for(2s); // booted at about 0.55 s (node 3 fails: 0x8182 at 1.55 s)
        ASSERT_EQ(value("State1.State"), kStandstill);
        ASSERT_FALSE(device.plc().runtime().write_value<std::uint8_t>("Main.Go", 1));
        device.loop().run_for(200ms); // both axes moving, for about 2 s
    }
    std::string value(const std::string& path) { return *device.plc().value_of("Main." + path); }
    drives::epos2::Epos2Drive& slave() { return *device.simulated_slaves().at(0); }
    /// The newest entries of the EPOS P's error history 0x1003, newest first.
    std::vector<ErrorEntry> history() {
        std::vector<ErrorEntry> entries;
        const auto count = device.objects().get_as<std::uint8_t>(0x1003, 0);
        for (std::uint8_t sub = 1; sub <= count; ++sub) {
            entries.push_back(
                ErrorEntry::decode(device.objects().get_as<std::uint32_t>(0x1003, sub)));
        }
        return entries;
    }
    bool in_history(std::uint16_t code, std::uint8_t port, std::uint8_t node) {
        for (const ErrorEntry& entry : history()) {
            if (entry.code == code && entry.port == port && entry.node == node) {
                return true;
            }
        }
        return false;
    }
    /// Frames with `id` on `bus` from now on.
    std::shared_ptr<int> count_frames(can::VirtualBus& bus, std::uint32_t id) {
        auto count = std::make_shared<int>(0);
        bus.add_observer([count, id](const can::WireEvent& event) {
            if (!event.frame.error && event.frame.id == id) {
                ++*count;
            }
        });
        return count;
    }

    EposP device;
};

TEST_F(FaultInjection, ADroppedHeartbeatIsALifeguardErrorAndErrorStopUntilTheNodeBootsAgain) {
    const auto heartbeats = count_frames(device.external_bus(), 0x702);
    ASSERT_FALSE(device.faults().drop_heartbeat(AxisTarget{1}));
    device.loop().run_for(400ms);
    EXPECT_EQ(*heartbeats, 0);
    EXPECT_TRUE(in_history(0x8130, kExternalPort, 2));
    EXPECT_FALSE(device.network(kExternalPort).booted(2));
    EXPECT_EQ(value("State1.State"), kErrorStop);
    EXPECT_EQ(value("Move1.Error"), "TRUE");
    EXPECT_EQ(value("Move0.Busy"), "TRUE") << "the other axis goes on";

    ASSERT_FALSE(device.faults().restore_heartbeat(AxisTarget{1}));
    device.loop().run_for(1s);
    EXPECT_TRUE(device.network(kExternalPort).booted(2)) << "booted again after its boot-up";
    EXPECT_GT(*heartbeats, 10);
    EXPECT_EQ(slave().state(), drives::motion::DriveState::SwitchOnDisabled) << "powered up";
    EXPECT_EQ(value("State1.State"), kErrorStop) << "until MC_Reset";
    ASSERT_FALSE(device.plc().runtime().write_value<std::uint8_t>("Main.DoReset", 1));
    device.loop().run_for(300ms);
    EXPECT_EQ(value("Reset1.Done"), "TRUE");
    EXPECT_EQ(value("State1.State"), kStandstill) << "MC_Power still enables it";
}

TEST_F(FaultInjection, TheInternalEpos2FallsSilentByItsNodeOnPort1) {
    ASSERT_FALSE(device.faults().drop_heartbeat(NodeTarget{kInternalPort, 1}));
    ASSERT_FALSE(device.faults().drop_heartbeat(NodeTarget{kInternalPort, 1})) << "twice: no-op";
    device.loop().run_for(400ms);
    EXPECT_TRUE(in_history(0x8130, kInternalPort, 1));
    EXPECT_EQ(value("State0.State"), kErrorStop);
    EXPECT_EQ(value("State1.State"), "3") << "axis 1 still in DiscreteMotion";
}

TEST_F(FaultInjection, RestoringANodeThatIsNotSilentChangesNothing) {
    ASSERT_FALSE(device.faults().restore_heartbeat(AxisTarget{1}));
    device.loop().run_for(200ms);
    EXPECT_EQ(value("State1.State"), "3");
    EXPECT_EQ(slave().state(), drives::motion::DriveState::OperationEnable);
}

// EPOS2 FW spec 8.2.57 / 4.2.28: the switch is executed once 0x2071 sub 4 has it (a program would
// write it by SDO, or the slave's DCF); then the drive raises 0xFF07 and the axis stops.
TEST_F(FaultInjection, ATrippedLimitSwitchIsTheDrivesLimitErrorAndErrorStop) {
    slave().objects().set_as(0x2071, 4, std::uint16_t{0x0003});
    ASSERT_FALSE(device.faults().set_limit_switch(AxisTarget{1}, LimitSwitch::Positive, true));
    device.loop().run_for(300ms);
    EXPECT_EQ(value("State1.State"), kErrorStop);
    EXPECT_EQ(value("Error1.AxisErrorID"), std::to_string(0xFF07));
    EXPECT_EQ(slave().objects().get_as<std::uint16_t>(0x2071, 1) & 0x3, 0x2);

    ASSERT_FALSE(device.faults().set_limit_switch(AxisTarget{1}, LimitSwitch::Positive, false));
    device.loop().run_for(10ms);
    EXPECT_EQ(slave().objects().get_as<std::uint16_t>(0x2071, 1) & 0x3, 0);
}

TEST_F(FaultInjection, ARaisedDriveErrorIsFaultWithItsCodeAndRegister) {
    ASSERT_FALSE(device.faults().raise_drive_error(AxisTarget{1}, 0x2310));
    device.loop().run_for(100ms);
    EXPECT_EQ(slave().state(), drives::motion::DriveState::Fault);
    EXPECT_EQ(slave().objects().get_as<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x2310U);
    EXPECT_EQ(value("State1.State"), kErrorStop);
    EXPECT_EQ(value("Error1.AxisErrorID"), std::to_string(0x2310));
    // 10.3: bits 0..7 of 0x1002 are the error register the slave's EMCY carried.
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1002, 0) & 0xFF, 0x02U);
}

TEST_F(FaultInjection, AnUnknownDriveErrorCodeIsRefused) {
    const auto error = device.faults().raise_drive_error(AxisTarget{1}, 0x1234);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->message, "0x1234 is not an EPOS2 error code (EPOS2 FW spec table 4-11)");
    device.loop().run_for(50ms);
    EXPECT_EQ(value("State1.State"), "3");
}

// A short TPDO 1 of the slave (statusword, position) reaches the EPOS P's RPDO: 0x8210 with
// port 2 (table 1); the next full one is taken again.
TEST_F(FaultInjection, AShortenedTpdoIsAPdoLengthErrorOfThePort) {
    ASSERT_FALSE(
        device.faults().corrupt_pdo(AxisTarget{1}, PdoDirection::Tpdo, 1, PdoFault::Shorten, 1));
    device.loop().run_for(10ms);
    EXPECT_TRUE(in_history(0x8210, kExternalPort, 0));
}

// A short RPDO 1 (controlword, target) at the slave: its own 0x8210, an "a" error (0x6007).
TEST_F(FaultInjection, AShortenedRpdoIsThePdoLengthErrorOfTheDrive) {
    ASSERT_FALSE(
        device.faults().corrupt_pdo(AxisTarget{1}, PdoDirection::Rpdo, 1, PdoFault::Shorten, 1));
    device.loop().run_for(300ms);
    EXPECT_EQ(slave().objects().get_as<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x8210U);
    EXPECT_EQ(value("State1.State"), kErrorStop);
}

// DeviceAxisLink: an axis whose statusword stops coming for 10 SYNCs is lost.
TEST_F(FaultInjection, DroppedTpdosLoseTheAxis) {
    ASSERT_FALSE(
        device.faults().corrupt_pdo(AxisTarget{1}, PdoDirection::Tpdo, 1, PdoFault::Drop, 20));
    device.loop().run_for(50ms);
    EXPECT_EQ(value("State1.State"), kErrorStop);
    EXPECT_EQ(value("State0.State"), "3");
}

TEST_F(FaultInjection, FramesByCobIdOnEitherPort) {
    const auto seen = count_frames(device.internal_bus(), 0x181);
    ASSERT_FALSE(device.faults().corrupt_frames(kInternalPort, 0x181, PdoFault::Drop, 5));
    ASSERT_FALSE(device.faults().corrupt_frames(kInternalPort, 0x181, PdoFault::Drop, 5));
    device.loop().run_for(30ms);
    EXPECT_EQ(*seen, 20) << "30 SYNCs, the first 10 TPDOs dropped";
}

TEST_F(FaultInjection, WrongTargetsAreRefusedWithTheirReason) {
    FaultInjector& faults = device.faults();
    const auto refused = [](const std::optional<core::Error>& error) {
        return error ? error->message : std::string("accepted");
    };
    EXPECT_EQ(refused(faults.drop_heartbeat(AxisTarget{32})),
              "axis 32: the axis table has axes 0..31");
    EXPECT_EQ(refused(faults.drop_heartbeat(AxisTarget{5})),
              "axis 5 has no slave (0x5285 sub 1 = 255, unassigned)");
    EXPECT_EQ(refused(faults.drop_heartbeat(NodeTarget{kExternalPort, 9})),
              "no simulated EPOS2 is node 9 on port 2");
    EXPECT_EQ(refused(faults.drop_heartbeat(NodeTarget{kInternalPort, 2})),
              "no simulated EPOS2 is node 2 on port 1");
    EXPECT_EQ(refused(faults.raise_drive_error(AxisTarget{2}, 0x2310)),
              "node 3 on port 2 is a slave of another process or real hardware (kind external): "
              "faults inside it cannot be injected from here");
    EXPECT_EQ(refused(faults.set_limit_switch(NodeTarget{3, 1}, LimitSwitch::Negative, true)),
              "port 3: the EPOS P has ports 1 (internal) and 2 (CAN)");
    EXPECT_EQ(refused(faults.restore_heartbeat(NodeTarget{kExternalPort, 0})),
              "node 0: a node-ID is 1..127");
    EXPECT_EQ(refused(faults.corrupt_pdo(AxisTarget{1}, PdoDirection::Tpdo, 5, PdoFault::Drop, 1)),
              "PDO 5: an EPOS2 has PDOs 1..4");
    slave().objects().set_as(0x1403, 1, std::uint32_t{0x8000'0502});
    EXPECT_EQ(refused(faults.corrupt_pdo(AxisTarget{1}, PdoDirection::Rpdo, 4, PdoFault::Drop, 1)),
              "RPDO 4 of node 2 on port 2 is not valid (0x1403 sub 1 = 0x80000502)");
    EXPECT_EQ(refused(faults.corrupt_frames(kExternalPort, 0x800, PdoFault::Drop, 1)),
              "COB-ID 0x800: an 11-bit identifier is 0..0x7FF");
    EXPECT_EQ(refused(faults.corrupt_frames(kExternalPort, 0x182, PdoFault::Drop, 0)),
              "a frame fault takes at least one frame");
    // Frames of the external slave's COB-IDs can be damaged on the bus all the same.
    EXPECT_EQ(refused(faults.corrupt_frames(kExternalPort, 0x183, PdoFault::Shorten, 1)),
              "accepted");
}

} // namespace
} // namespace eposp::device
