// The motion blocks on the EPOS P's own network (device/src/device_axis_link.cpp): simulated
// EPOS2s on both ports, moved, stopped by a drive fault and by a lost heartbeat, and the
// pick-and-place example as a user runs it.

#include "compile_program.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp_command.hpp"

#include <chrono>
#include <cmath>
#include <gtest/gtest.h>
#include <optional>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;

constexpr std::string_view kNetwork = R"(
sync_period: 1ms
boot_time: 500ms
slaves:
  - {node: 1, port: internal, axis: 0, heartbeat: 100ms}
  - {node: 2, axis: 1, heartbeat: 100ms}
)";

constexpr std::string_view kProgram = R"ST(
PROGRAM Main
VAR
  Axis0 : AXIS_REF := (AxisNo := 0);
  Axis1 : AXIS_REF := (AxisNo := 1);
  Power0, Power1 : MC_Power;
  Move0, Move1 : MC_MoveAbsolute;
  State1 : MC_ReadAxisState;
  Error1 : MC_ReadAxisError;
  Go : BOOL;
END_VAR
Power0(Axis := Axis0, Enable := TRUE);
Power1(Axis := Axis1, Enable := TRUE);
Move0(Axis := Axis0, Execute := Go, Position := 20000, Velocity := 3000,
      Acceleration := 10000, Deceleration := 10000);
Move1(Axis := Axis1, Execute := Go, Position := -12000, Velocity := 3000,
      Acceleration := 10000, Deceleration := 10000);
State1(Axis := Axis1, Enable := TRUE);
Error1(Axis := Axis1, Enable := TRUE);
END_PROGRAM
CONFIGURATION Cell
  RESOURCE EposP ON EPOS_P
    TASK Motion (INTERVAL := T#1ms, PRIORITY := 1);
    PROGRAM Main WITH Motion : Main;
  END_RESOURCE
END_CONFIGURATION
)ST";

/// Puts `network` and `program` on `device` and starts the program cold.
void start(EposP& device, const core::Result<NetworkFile>& network, const std::string& program) {
    ASSERT_TRUE(network) << network.error();
    device.add_network(*network);
    ASSERT_FALSE(device.plc().load(compile_program(program)));
    ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
}

/// A variable of the program instance Main, as an IEC literal.
std::string value(EposP& device, const std::string& path) {
    return *device.plc().value_of("Main." + path);
}

class MotionOnNetwork : public testing::Test {
protected:
    void SetUp() override {
        start(device, parse_network_file(kNetwork, "net.yaml"), std::string(kProgram));
        device.loop().run_for(1s); // booted at about 0.55 s, then powered
    }
    std::string value(const std::string& path) { return device::value(device, path); }
    std::int32_t actual_position(std::size_t slave) {
        return device.simulated_slaves()[slave]->objects().get_as<std::int32_t>(0x6064, 0);
    }
    void go() { ASSERT_FALSE(device.plc().runtime().write_value<std::uint8_t>("Main.Go", 1)); }

    EposP device;
};

TEST_F(MotionOnNetwork, BothAxesArePoweredAndMoveToTheirTargets) {
    EXPECT_EQ(value("Power0.Status"), "TRUE");
    EXPECT_EQ(value("Power1.Status"), "TRUE");
    EXPECT_EQ(value("State1.State"), "1"); // Standstill
    go();
    device.loop().run_for(100ms);
    EXPECT_EQ(value("Move1.Busy"), "TRUE");
    EXPECT_EQ(value("State1.State"), "3"); // DiscreteMotion
    device.loop().run_for(3s);
    EXPECT_EQ(value("Move0.Done"), "TRUE");
    EXPECT_EQ(value("Move1.Done"), "TRUE");
    EXPECT_EQ(value("State1.State"), "1");
    EXPECT_EQ(device.internal_drive().objects().get_as<std::int32_t>(0x6064, 0), 20000);
    EXPECT_EQ(actual_position(0), -12000);
}

/// Seconds a move of `distance` qc takes on the drive's trapezoidal profile from rest to rest
/// (v rpm, a rpm/s, 2000 qc per turn on the reference axis): a triangle when it is too short to
/// reach v.
double profile_time(double distance, double v, double a) {
    const double turns = std::abs(distance) / 2000.0;
    const double rps = v / 60.0;
    const double rps2 = a / 60.0;
    const double ramps = rps * rps / rps2; // the turns both ramps take
    return turns >= ramps ? turns / rps + rps / rps2 : 2 * std::sqrt(turns / rps2);
}

TEST_F(MotionOnNetwork, MovesAreDoneWhenTheirProfileEnds) {
    go();
    std::optional<double> started[2];
    std::optional<double> done[2];
    for (int ms = 1; ms <= 2000 && !(done[0] && done[1]); ++ms) {
        device.loop().run_for(1ms);
        const double now = ms / 1000.0;
        for (const int axis : {0, 1}) {
            const std::string move = "Move" + std::to_string(axis);
            if (!started[axis] && value(move + ".Active") == "TRUE") {
                started[axis] = now;
            }
            if (!done[axis] && value(move + ".Done") == "TRUE") {
                done[axis] = now;
            }
        }
    }
    ASSERT_TRUE(done[0] && done[1]);
    // From the cycle the block became Active: the profile parameters go out by SDO and the
    // set-point handshake takes two SYNCs each way; the drive's target reached comes with the
    // next TPDO. Together under 10 ms.
    const double expected[2] = {profile_time(20000, 3000, 10000), profile_time(12000, 3000, 10000)};
    for (const int axis : {0, 1}) {
        const double took = *done[axis] - *started[axis];
        EXPECT_GE(took, expected[axis]) << "axis " << axis;
        EXPECT_LE(took, expected[axis] + 0.010) << "axis " << axis;
    }
}

TEST_F(MotionOnNetwork, ADriveFaultMidMoveIsErrorStopWithTheDrivesErrorCode) {
    go();
    device.loop().run_for(200ms);
    device.simulated_slaves()[0]->set_supply_voltage(5.0); // undervoltage
    device.loop().run_for(200ms);
    EXPECT_EQ(value("State1.State"), "6"); // ErrorStop
    EXPECT_EQ(value("Move1.Error"), "TRUE");
    EXPECT_EQ(value("Move1.ErrorID"), "4100"); // 16#1004
    const auto code =
        device.simulated_slaves()[0]->objects().get_as<std::uint32_t>(0x1003, 1) & 0xFFFF;
    EXPECT_NE(code, 0);
    EXPECT_EQ(value("Error1.AxisErrorID"), std::to_string(code));
    EXPECT_EQ(value("Move0.Busy"), "TRUE"); // the other axis goes on
}

TEST_F(MotionOnNetwork, ALostHeartbeatMidMoveIsErrorStop) {
    go();
    device.loop().run_for(200ms);
    device.external_bus().drop_frames([](const can::Frame& frame) { return frame.id == 0x702; },
                                      1000);
    device.loop().run_for(400ms);
    EXPECT_EQ(value("State1.State"), "6");
    EXPECT_EQ(value("Move1.ErrorID"), "4099"); // 16#1003
    EXPECT_EQ(value("Error1.AxisErrorID"), "4099");
}

TEST(MotionOnNetworkPolling, AMoveGoesOnWhenItsBlockIsNoLongerCalled) {
    const auto network = parse_network_file(kNetwork, "net.yaml");
    EposP device;
    start(device, network, R"ST(
PROGRAM Main
VAR
  Axis1 : AXIS_REF := (AxisNo := 1);
  Power : MC_Power;
  Move : MC_MoveAbsolute;
  Calls : INT;
  Powered : BOOL;
END_VAR
(* Power until it is on, then two calls of the move, then no block at all. *)
IF NOT Powered THEN
  Power(Axis := Axis1, Enable := TRUE);
  Powered := Power.Status;
ELSIF Calls < 2 THEN
  Move(Axis := Axis1, Execute := TRUE, Position := 8000, Velocity := 3000,
       Acceleration := 10000, Deceleration := 10000);
  Calls := Calls + 1;
END_IF;
END_PROGRAM
)ST");
    device.loop().run_for(2s);
    const auto& drive = device.simulated_slaves()[0]->objects();
    EXPECT_EQ(drive.get_as<std::int32_t>(0x6064, 0), 8000);
    // The set-point handshake was finished for it: the new set-point bit is low again.
    EXPECT_EQ(drive.get_as<std::uint16_t>(0x6040, 0) & 0x10, 0);
    EXPECT_EQ(device.motion().axis(1).state(), plcopen::AxisState::Standstill);
}

// A buffered sequence of three moves on the EPOS2: the second and third wait in the drive's
// set-point buffer, so the sequence takes the three profiles' time plus the first move's start
// (its SDO parameters and handshake), with no stop between the moves.
TEST(MotionOnNetworkBuffered, ThreeBufferedMovesRunBackToBack) {
    const auto network = parse_network_file(kNetwork, "net.yaml");
    EposP device;
    start(device, network, R"ST(
PROGRAM Main
VAR
  Axis1 : AXIS_REF := (AxisNo := 1);
  Power : MC_Power;
  First, Second, Third : MC_MoveAbsolute;
  Go : BOOL;
END_VAR
Power(Axis := Axis1, Enable := TRUE);
Go := Power.Status;
First(Axis := Axis1, Execute := Go, Position := 6000, Velocity := 3000, Acceleration := 10000,
      Deceleration := 10000);
Second(Axis := Axis1, Execute := Go, Position := 2000, Velocity := 1500, Acceleration := 10000,
       Deceleration := 10000, BufferMode := mcBuffered);
Third(Axis := Axis1, Execute := Go, Position := 9000, Velocity := 3000, Acceleration := 20000,
      Deceleration := 20000, BufferMode := mcBuffered);
END_PROGRAM
)ST");
    std::optional<double> started;
    std::optional<double> done;
    std::optional<double> first_done;
    for (int ms = 1; ms <= 5000 && !done; ++ms) {
        device.loop().run_for(1ms);
        if (!started && value(device, "First.Active") == "TRUE") {
            started = ms / 1000.0;
        }
        if (!first_done && value(device, "First.Done") == "TRUE") {
            first_done = ms / 1000.0;
            EXPECT_EQ(value(device, "Second.Active"), "TRUE");
        }
        if (value(device, "Third.Done") == "TRUE") {
            done = ms / 1000.0;
        }
    }
    ASSERT_TRUE(started && first_done && done);
    EXPECT_EQ(value(device, "First.CommandAborted"), "FALSE");
    EXPECT_EQ(value(device, "Second.Done"), "TRUE");
    const double profiles = profile_time(6000, 3000, 10000) + profile_time(4000, 1500, 10000) +
                            profile_time(7000, 3000, 20000);
    EXPECT_GE(*done - *started, profiles);
    EXPECT_LE(*done - *started, profiles + 0.010) << "the profiles take " << profiles << " s";
    EXPECT_NEAR(device.simulated_slaves()[0]->objects().get_as<std::int32_t>(0x6064, 0), 9000,
                10); // within the drive's position window
}

// Axes 16..31 have their process data in the other half of the process image; the blocks move
// them like any other, and a program sees the same values at %IW(n) and %ID(24+n).
TEST(MotionOnNetworkHighAxes, Axis31IsPoweredAndMoved) {
    const auto network =
        parse_network_file("sync_period: 1ms\nslaves:\n  - {node: 4, axis: 31}\n", "net.yaml");
    EposP device;
    start(device, network, R"ST(
PROGRAM Main
VAR
  Far : AXIS_REF := (AxisNo := 31);
  Power : MC_Power;
  Move : MC_MoveAbsolute;
  Status AT %IW31 : WORD;
  Position AT %ID55 : DINT;
END_VAR
Power(Axis := Far, Enable := TRUE);
Move(Axis := Far, Execute := Power.Status, Position := -7000, Velocity := 3000,
     Acceleration := 10000, Deceleration := 10000);
END_PROGRAM
)ST");
    device.loop().run_for(3s);
    EXPECT_EQ(value(device, "Move.Done"), "TRUE") << value(device, "Move.ErrorID");
    const std::int32_t actual =
        device.simulated_slaves()[0]->objects().get_as<std::int32_t>(0x6064, 0);
    EXPECT_NEAR(actual, -7000, 10);
    EXPECT_EQ(value(device, "Position"), std::to_string(actual));
    EXPECT_EQ(std::stoi(value(device, "Status")) & 0x6F, 0x27) // Operation enabled
        << value(device, "Status");
}

// A following error window far too tight for the move (MC_WriteParameter 7, MaxPositionLag
// 0x6065): the drive faults with 0x8611 and the axis goes to ErrorStop; MC_Reset clears it.
TEST(MotionOnNetworkLimits, AFollowingErrorIsErrorStopWithItsCodeAndResetClearsIt) {
    const auto network = parse_network_file(kNetwork, "net.yaml");
    EposP device;
    start(device, network, R"ST(
PROGRAM Main
VAR
  Axis1 : AXIS_REF := (AxisNo := 1);
  Power : MC_Power;
  TightLag : MC_WriteParameter;
  Move : MC_MoveAbsolute;
  AxisError : MC_ReadAxisError;
  State : MC_ReadAxisState;
  Reset : MC_Reset;
  DoReset : BOOL;
END_VAR
Power(Axis := Axis1, Enable := TRUE);
TightLag(Axis := Axis1, Execute := Power.Status, ParameterNumber := 7, Value := 2);
Move(Axis := Axis1, Execute := TightLag.Done AND NOT DoReset, Position := 50000, Velocity := 8000,
     Acceleration := 100000, Deceleration := 100000);
AxisError(Axis := Axis1, Enable := TRUE);
State(Axis := Axis1, Enable := TRUE);
Reset(Axis := Axis1, Execute := DoReset);
END_PROGRAM
)ST");
    device.loop().run_for(2s);
    EXPECT_EQ(value(device, "State.State"), "6"); // ErrorStop
    EXPECT_EQ(value(device, "AxisError.AxisErrorID"), std::to_string(0x8611));
    ASSERT_FALSE(device.plc().runtime().write_value<std::uint8_t>("Main.DoReset", 1));
    device.loop().run_for(200ms);
    EXPECT_EQ(value(device, "Reset.Done"), "TRUE");
    EXPECT_EQ(value(device, "State.State"), "1"); // Standstill: powered again, no move
    EXPECT_EQ(value(device, "AxisError.AxisErrorID"), "0");
}

// MC_Reset given the cycle the axis enters ErrorStop, while the drive still runs its fault
// reaction (statusword x0xx 1111, FW spec table 3-4): a fault reset acts only from Fault (table
// 3-5, transition 15), so the block waits for Fault, then resets, and does not fail.
TEST(MotionOnNetworkLimits, AResetDuringTheFaultReactionWaitsForFaultThenClearsIt) {
    const auto network = parse_network_file(kNetwork, "net.yaml");
    EposP device;
    start(device, network, R"ST(
PROGRAM Main
VAR
  Axis1 : AXIS_REF := (AxisNo := 1);
  Power : MC_Power;
  TightLag : MC_WriteParameter;
  Move : MC_MoveAbsolute;
  Status : MC_ReadStatus;
  Reset : MC_Reset;
  Faulted, ResetFailed : BOOL;
END_VAR
Power(Axis := Axis1, Enable := TRUE);
TightLag(Axis := Axis1, Execute := Power.Status, ParameterNumber := 7, Value := 2);
Move(Axis := Axis1, Execute := TightLag.Done AND NOT Faulted, Position := 50000, Velocity := 8000,
     Acceleration := 100000, Deceleration := 100000);
Status(Axis := Axis1, Enable := TRUE);
Faulted := Faulted OR Status.ErrorStop;
Reset(Axis := Axis1, Execute := Status.ErrorStop OR Reset.Busy OR Reset.Done);
ResetFailed := ResetFailed OR Reset.Error;
END_PROGRAM
)ST");
    device.loop().run_for(2s);
    EXPECT_EQ(value(device, "Faulted"), "TRUE");
    EXPECT_EQ(value(device, "ResetFailed"), "FALSE");
    EXPECT_EQ(value(device, "Reset.Done"), "TRUE");
    EXPECT_EQ(value(device, "Status.Standstill"), "TRUE"); // powered again
}

TEST(MotionOnNetworkLimits, ALimitSwitchStopsTheAxisInErrorStopWithItsErrorCode) {
    write_source("machine.yaml", "switches:\n  positive_limit: 15000\n");
    const auto network = load_network_file(write_source(
        "net.yaml", "sync_period: 1ms\nslaves:\n  - {node: 2, axis: 1, plant: machine.yaml}\n"));
    EposP device;
    start(device, network, R"ST(
PROGRAM Main
VAR
  Axis1 : AXIS_REF := (AxisNo := 1);
  Power : MC_Power;
  ExecuteLimits : MC_WriteParameter;
  Move : MC_MoveAbsolute;
  State : MC_ReadAxisState;
  AxisError : MC_ReadAxisError;
END_VAR
Power(Axis := Axis1, Enable := TRUE);
(* 0x2071 sub 4: the limit switches stop the drive (bits 0 and 1 of the execution mask) *)
ExecuteLimits(Axis := Axis1, Execute := Power.Status, ParameterNumber := 16#207104, Value := 3);
Move(Axis := Axis1, Execute := ExecuteLimits.Done, Position := 20000, Velocity := 3000,
     Acceleration := 10000, Deceleration := 10000);
State(Axis := Axis1, Enable := TRUE);
AxisError(Axis := Axis1, Enable := TRUE);
END_PROGRAM
)ST");
    device.loop().run_for(2s);
    const auto value = [&](const std::string& path) {
        return device::value(device, path);
    };
    EXPECT_EQ(value("State.State"), "6");               // ErrorStop
    EXPECT_EQ(value("AxisError.AxisErrorID"), "65287"); // 16#FF07 positive limit switch
    const auto position = device.simulated_slaves()[0]->objects().get_as<std::int32_t>(0x6064, 0);
    EXPECT_GE(position, 15000);
    EXPECT_LT(position, 20000);
}

TEST(MaxonBlocksOnNetwork, SdoAndNmtReachAnySlaveAndTheErrorHistoryOfTheEposP) {
    EposP device;
    start(device, parse_network_file(kNetwork, "net.yaml"), R"ST(
PROGRAM Main
VAR
  Controller : AXIS_REF := (AxisNo := 255);
  Vendor : CAN_SdoRead;
  Heartbeat : CAN_SdoWrite;
  Stop : CAN_Nmt;
  Errors : MU_GetDeviceErrorCount;
  Go, StopIt : BOOL;
END_VAR
Vendor(Execute := Go, Port := 2, NodeId := 2, Index := 16#1018, SubIndex := 1);
Heartbeat(Execute := Go, Port := 2, NodeId := 2, Index := 16#1017, SubIndex := 0, Data := 40,
          DataLength := 2);
Stop(Execute := StopIt, Port := 2, NodeId := 2, Command := 2);
Errors(Axis := Controller, Enable := TRUE);
END_PROGRAM
)ST");
    device.loop().run_for(1s);
    ASSERT_FALSE(device.plc().runtime().write_value<std::uint8_t>("Main.Go", 1));
    device.loop().run_for(50ms);
    const auto value = [&](const std::string& path) {
        return device::value(device, path);
    };
    EXPECT_EQ(value("Vendor.Done"), "TRUE");
    EXPECT_EQ(value("Vendor.Data"), "251"); // maxon's vendor-ID 0xFB
    EXPECT_EQ(value("Heartbeat.Done"), "TRUE");
    EXPECT_EQ(device.simulated_slaves()[0]->objects().get_as<std::uint16_t>(0x1017, 0), 40);
    EXPECT_EQ(value("Errors.Valid"), "TRUE");
    EXPECT_EQ(value("Errors.ErrorCount"),
              std::to_string(device.objects().get_as<std::uint8_t>(0x1003, 0)));
    ASSERT_FALSE(device.plc().runtime().write_value<std::uint8_t>("Main.StopIt", 1));
    device.loop().run_for(20ms);
    EXPECT_EQ(value("Stop.Done"), "TRUE");
    EXPECT_EQ(device.simulated_slaves()[0]->node().nmt_state(), canopen::NmtState::Stopped);
}

/// Runs examples/NAME/run.sh into the test's own directory; its output.
std::string run_example(const std::string& name) {
    const auto dir = scratch("demo");
    const auto result =
        test::run_command("EPOSP_DEMO_DIR=" + dir.string() + " " + EPOSP_SOURCE_DIR + "/examples/" +
                          name + "/run.sh " + kEposp + " 2>&1");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(std::filesystem::exists(dir / (name + ".svg"))) << result.output;
    return result.output;
}

TEST_F(MotionOnNetwork, StoppedProcessDataMidMoveAreErrorStop) {
    go();
    device.loop().run_for(200ms);
    // The slave's TPDO 1 (statusword, position) stops; its heartbeat goes on.
    device.external_bus().drop_frames([](const can::Frame& frame) { return frame.id == 0x182; },
                                      100000);
    device.loop().run_for(30ms);
    EXPECT_EQ(value("State1.State"), "6");
    EXPECT_EQ(value("Move1.ErrorID"), "4099"); // 16#1003
    EXPECT_EQ(value("Move0.Busy"), "TRUE");    // the other axis goes on
}

// The eight-axis benchmark of docs/performance.md runs as measured: every axis moves.
TEST(MotionBenchmark, EightAxesMoveBackAndForthOnOneBus) {
    const std::string bench = std::string(EPOSP_SOURCE_DIR) + "/tests/bench/";
    const auto result = eposp("run " + bench + "epos_p_motion8.st --network " + bench +
                              "epos_p_motion8.yaml --for 2s --watch Main.Moves");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output.find("error"), std::string::npos) << result.output;
    // 1.45 s after the boot, moves of about 0.38 s: at least three on each of the eight axes.
    const auto moves = result.output.find("Main.Moves = ");
    ASSERT_NE(moves, std::string::npos) << result.output;
    EXPECT_GE(std::stoi(result.output.substr(moves + 13)), 24) << result.output;
}

TEST(MotionExamples, ThePickAndPlaceCellRunsItsThreeCycles) {
    const std::string output = run_example("pick-and-place");
    EXPECT_NE(output.find("Main.Cycles = 3\nMain.Step = 14\nMain.Failed = FALSE"),
              std::string::npos)
        << output;
    // The carriage at the place position while the lift goes down for the first time.
    EXPECT_NE(output.find("1.75 s   carriage   40000 qc      0 rpm"), std::string::npos) << output;
}

TEST(MotionExamples, HomingOnTheSwitchThenThreeMoves) {
    const std::string output = run_example("homing-then-move");
    EXPECT_NE(output.find("Main.Step = 6\nMain.Visited = 3\nMain.Failed = FALSE\n"
                          "Main.Position.Position = 0"),
              std::string::npos)
        << output;
    EXPECT_NE(output.find("Homing"), std::string::npos) << output;
    EXPECT_NE(output.find("3.75 s     19999 qc      0 rpm   Standstill"), std::string::npos)
        << output;
}

TEST(MotionExamples, TheConveyorRunsWhenThePushersSensorSeesAPart) {
    const std::string output = run_example("conveyor");
    EXPECT_NE(output.find("Main.Parts = 7\nMain.Failed = FALSE"), std::string::npos) << output;
    // The belt runs at 1500 rpm after the first part, then halts where the halt ends.
    EXPECT_NE(output.find("1.50 s   belt   18247 qc  1470 rpm ContinuousMotion"), std::string::npos)
        << output;
    EXPECT_NE(output.find("2.50 s   belt   60051 qc     0 rpm Standstill"), std::string::npos)
        << output;
}

} // namespace
} // namespace eposp::device
