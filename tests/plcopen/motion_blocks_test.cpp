// The motion blocks against a fake drive (fake_drive_link.hpp), cycle by cycle: the PLCopen
// state diagram, the output rules of Execute blocks, and the CiA 402 handshakes underneath.

#include "motion_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::plcopen::test {
namespace {

// Axis 1 with every block of a simple machine, each started by a BOOL of its own.
constexpr std::string_view kProgram = R"ST(
PROGRAM Main
VAR
  Axis1 : AXIS_REF := (AxisNo := 1);
  Power : MC_Power;
  Move : MC_MoveAbsolute;
  Move2 : MC_MoveAbsolute;
  Relative : MC_MoveRelative;
  Additive : MC_MoveAdditive;
  Velocity, Velocity2 : MC_MoveVelocity;
  HaltIt : MC_Halt;
  StopIt : MC_Stop;
  ResetIt : MC_Reset;
  Home : MC_Home;
  Status : MC_ReadStatus;
  State : MC_ReadAxisState;
  AxisError : MC_ReadAxisError;
  Actual : MC_ReadActualPosition;
  Enable, Go, Go2, GoRelative, GoAdditive, GoVelocity, GoVelocity2, GoHalt, GoStop, GoReset,
  GoHome : BOOL;
  Target : DINT := 1000;
  Target2 : DINT := 2000;
  Speed : DINT := 100;
  Mode2 : MC_BUFFER_MODE := mcAborting;
END_VAR
Power(Axis := Axis1, Enable := Enable);
Move(Axis := Axis1, Execute := Go, Position := Target, Velocity := Speed, Acceleration := 1000,
     Deceleration := 1000);
Move2(Axis := Axis1, Execute := Go2, Position := Target2, Velocity := 100, Acceleration := 1000,
      Deceleration := 1000, BufferMode := Mode2);
Relative(Axis := Axis1, Execute := GoRelative, Distance := 50, Velocity := 100,
         Acceleration := 1000, Deceleration := 1000);
Additive(Axis := Axis1, Execute := GoAdditive, Distance := 50, Velocity := 100,
         Acceleration := 1000, Deceleration := 1000);
Velocity(Axis := Axis1, Execute := GoVelocity, Velocity := 10, Acceleration := 1000,
         Deceleration := 1000, Direction := mcNegativeDirection);
Velocity2(Axis := Axis1, Execute := GoVelocity2, Velocity := 20, Acceleration := 1000,
          Deceleration := 1000);
HaltIt(Axis := Axis1, Execute := GoHalt, Deceleration := 1000);
StopIt(Axis := Axis1, Execute := GoStop, Deceleration := 1000);
ResetIt(Axis := Axis1, Execute := GoReset);
Home(Axis := Axis1, Execute := GoHome, Position := 77, HomingMethod := 35);
Status(Axis := Axis1, Enable := TRUE);
State(Axis := Axis1, Enable := TRUE);
AxisError(Axis := Axis1, Enable := TRUE);
Actual(Axis := Axis1, Enable := TRUE);
END_PROGRAM
)ST";

class MotionBlocks : public testing::TestWithParam<vm::Engine> {
protected:
    MotionBlocks() : h(GetParam()) { h.start(std::string(kProgram)); }

    AxisState state() const { return static_cast<AxisState>(h.get<std::uint8_t>("State.State")); }
    FakeDrive& drive() { return h.link.drives[1]; }
    /// Powers the axis on: Standstill.
    void power_on() {
        h.set_flag("Enable", true);
        h.cycle(8);
        ASSERT_EQ(state(), AxisState::Standstill);
    }
    /// Runs until `flag` is TRUE; false after `limit` cycles.
    bool cycle_until(std::string_view flag, int limit = 100) {
        for (int i = 0; i < limit; ++i) {
            h.cycle();
            if (h.flag(flag)) {
                return true;
            }
        }
        return false;
    }

    MotionHarness h;
};

TEST_P(MotionBlocks, PowerTakesTheAxisFromDisabledToStandstillAndBack) {
    h.cycle(3);
    EXPECT_EQ(state(), AxisState::Disabled);
    EXPECT_TRUE(h.flag("Status.Disabled"));
    EXPECT_FALSE(h.flag("Power.Status"));
    h.set_flag("Enable", true);
    EXPECT_TRUE(cycle_until("Power.Status", 10));
    EXPECT_TRUE(h.flag("Power.Valid"));
    h.cycle();
    EXPECT_EQ(state(), AxisState::Standstill);
    EXPECT_TRUE(h.flag("Status.Standstill"));
    EXPECT_EQ(drive().statusword & 0x6F, 0x27); // Operation enabled
    h.set_flag("Enable", false);
    h.cycle(4);
    EXPECT_EQ(state(), AxisState::Disabled);
    EXPECT_FALSE(h.flag("Power.Status"));
    EXPECT_EQ(drive().statusword & 0x6F, 0x21); // Ready to switch on: power stage off
}

TEST_P(MotionBlocks, MoveAbsoluteReachesItsTargetAndHoldsDoneWhileExecuteIsTrue) {
    power_on();
    h.set_flag("Go", true);
    h.cycle();
    EXPECT_TRUE(h.flag("Move.Busy"));
    EXPECT_TRUE(h.flag("Move.Active"));
    EXPECT_EQ(state(), AxisState::DiscreteMotion);
    ASSERT_TRUE(cycle_until("Move.Done"));
    EXPECT_EQ(drive().position, 1000);
    EXPECT_EQ(h.get<std::int32_t>("Actual.Position"), 1000);
    EXPECT_FALSE(h.flag("Move.Busy"));
    EXPECT_FALSE(h.flag("Move.Active"));
    // The profile the drive got: 0x6081 / 0x6083 / 0x6084, profile position mode.
    EXPECT_EQ(drive().object(0x6081), 100U);
    EXPECT_EQ(drive().object(0x6083), 1000U);
    EXPECT_EQ(drive().object(0x6060), 1U);
    h.cycle();
    EXPECT_EQ(state(), AxisState::Standstill);
    h.cycle(5);
    EXPECT_TRUE(h.flag("Move.Done")); // held while Execute stays TRUE
    h.set_flag("Go", false);
    h.cycle();
    EXPECT_FALSE(h.flag("Move.Done"));
}

TEST_P(MotionBlocks, DoneShowsForExactlyOneCycleWhenExecuteFellBefore) {
    power_on();
    h.set_flag("Go", true);
    h.cycle();
    h.set_flag("Go", false); // a pulse: the move goes on
    int done_cycles = 0;
    for (int i = 0; i < 40; ++i) {
        h.cycle();
        done_cycles += h.flag("Move.Done") ? 1 : 0;
    }
    EXPECT_EQ(drive().position, 1000);
    EXPECT_EQ(done_cycles, 1);
}

TEST_P(MotionBlocks, ARisingEdgeWhileBusyIsIgnored) {
    power_on();
    h.set_flag("Go", true);
    h.cycle(2);
    h.set_flag("Go", false);
    h.set<std::int32_t>("Target", 5000);
    h.cycle();
    h.set_flag("Go", true);
    ASSERT_TRUE(cycle_until("Move.Done"));
    EXPECT_EQ(drive().position, 1000);
}

TEST_P(MotionBlocks, MotionIsRefusedWhileDisabled) {
    h.cycle(2);
    h.set_flag("Go", true);
    h.cycle();
    EXPECT_TRUE(h.flag("Move.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("Move.ErrorID"), 0x1020);
    EXPECT_FALSE(h.flag("Move.Busy"));
    EXPECT_EQ(state(), AxisState::Disabled);
    h.set_flag("Go", false);
    h.cycle();
    EXPECT_FALSE(h.flag("Move.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("Move.ErrorID"), 0);
}

TEST_P(MotionBlocks, BadInputsAreErrorsOfTheBlockNotOfTheAxis) {
    power_on();
    h.set<std::int32_t>("Speed", -5);
    h.set_flag("Go", true);
    h.cycle();
    EXPECT_TRUE(h.flag("Move.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("Move.ErrorID"), 0x1010);
    EXPECT_EQ(state(), AxisState::Standstill);
}

TEST_P(MotionBlocks, AnAbortingMoveTakesOverAndTheFirstReportsCommandAborted) {
    power_on();
    h.set_flag("Go", true);
    h.cycle(6);
    ASSERT_TRUE(h.flag("Move.Busy"));
    h.set_flag("Go2", true);
    h.cycle(2); // Move, called before Move2, learns of it in the next cycle
    EXPECT_TRUE(h.flag("Move.CommandAborted"));
    EXPECT_FALSE(h.flag("Move.Busy"));
    EXPECT_FALSE(h.flag("Move.Done"));
    EXPECT_TRUE(h.flag("Move2.Active"));
    ASSERT_TRUE(cycle_until("Move2.Done"));
    EXPECT_EQ(drive().position, 2000);
    EXPECT_FALSE(h.flag("Move.Done"));
}

// A Buffered move after a position move waits in the drive's set-point buffer (EPOS2 firmware
// specification 5.3.2.3, "change set immediately" clear): the drive goes on to it the moment the
// first move ends, without a cycle at rest on the first target.
TEST_P(MotionBlocks, ABufferedMoveGoesOnFromTheDrivesBufferWithoutStopping) {
    power_on();
    h.set<std::int16_t>("Mode2", static_cast<std::int16_t>(BufferMode::Buffered));
    h.set_flag("Go", true);
    h.cycle(3);
    h.set_flag("Go2", true);
    h.cycle();
    EXPECT_TRUE(h.flag("Move2.Busy"));
    EXPECT_FALSE(h.flag("Move2.Active"));
    EXPECT_TRUE(h.flag("Move.Active"));
    h.cycle(6);
    ASSERT_TRUE(drive().buffered.has_value()) << "the second move should wait in the drive";
    EXPECT_EQ(drive().buffered->first, 2000);
    EXPECT_FALSE(h.flag("Move2.Active"));

    std::int32_t last = drive().position;
    bool first_done = false;
    for (int i = 0; i < 40 && drive().position < 2000; ++i) {
        h.cycle();
        ASSERT_GT(drive().position, last) << "the axis stood still at cycle " << i;
        last = drive().position;
        if (h.flag("Move.Done") && !first_done) {
            first_done = true;
            EXPECT_TRUE(h.flag("Move2.Active")); // in the same cycle
            EXPECT_GT(drive().position, 1000);
            EXPECT_EQ(state(), AxisState::DiscreteMotion);
        }
    }
    EXPECT_TRUE(first_done);
    EXPECT_FALSE(h.flag("Move.CommandAborted"));
    ASSERT_TRUE(cycle_until("Move2.Done"));
    EXPECT_EQ(drive().position, 2000);
    EXPECT_EQ(state(), AxisState::Standstill);
}

// A move that is already in the drive's buffer is aborted like any other: the aborting move's
// set-point ("change set immediately") empties the buffer, so the axis never goes there.
TEST_P(MotionBlocks, AnAbortingMoveAlsoEmptiesTheDrivesBuffer) {
    power_on();
    h.set<std::int32_t>("Speed", 20); // 50 cycles to the first target
    h.set<std::int16_t>("Mode2", static_cast<std::int16_t>(BufferMode::Buffered));
    h.set_flag("Go", true);
    h.cycle(3);
    h.set_flag("Go2", true);
    h.cycle(7);
    ASSERT_TRUE(drive().buffered.has_value());
    h.set_flag("GoRelative", true);
    h.cycle(2);
    EXPECT_TRUE(h.flag("Move.CommandAborted"));
    EXPECT_TRUE(h.flag("Move2.CommandAborted"));
    ASSERT_TRUE(cycle_until("Relative.Done"));
    EXPECT_FALSE(drive().buffered.has_value());
    const std::int32_t stopped_at = drive().position;
    EXPECT_LT(stopped_at, 500);
    h.cycle(20);
    EXPECT_EQ(drive().position, stopped_at);
}

TEST_P(MotionBlocks, RelativeMovesFromTheActualPositionAdditiveFromTheLastTarget) {
    power_on();
    drive().position = drive().taken_target = 300;
    h.set_flag("GoRelative", true);
    ASSERT_TRUE(cycle_until("Relative.Done"));
    EXPECT_EQ(drive().position, 350);
    h.set_flag("GoAdditive", true);
    ASSERT_TRUE(cycle_until("Additive.Done"));
    EXPECT_EQ(drive().position, 400);
}

TEST_P(MotionBlocks, VelocityThenHalt) {
    power_on();
    h.set_flag("GoVelocity", true);
    ASSERT_TRUE(cycle_until("Velocity.InVelocity"));
    EXPECT_EQ(state(), AxisState::ContinuousMotion);
    EXPECT_EQ(static_cast<std::int32_t>(drive().object(0x60FF)), -10); // mcNegativeDirection
    EXPECT_EQ(drive().object(0x6060), 3U);
    EXPECT_TRUE(h.flag("Velocity.Busy"));
    const std::int32_t moving_from = drive().position;
    h.cycle(3);
    EXPECT_EQ(drive().position, moving_from - 30);
    h.set_flag("GoHalt", true);
    h.cycle(2);
    EXPECT_TRUE(h.flag("Velocity.CommandAborted"));
    EXPECT_EQ(state(), AxisState::DiscreteMotion);
    ASSERT_TRUE(cycle_until("HaltIt.Done"));
    h.cycle();
    EXPECT_EQ(state(), AxisState::Standstill);
    const std::int32_t stopped_at = drive().position;
    h.cycle(3);
    EXPECT_EQ(drive().position, stopped_at);
}

// InVelocity is bit 10 "target velocity reached" (FW spec table 5-54) of the new velocity, not
// of a statusword sampled before the drive took 0x60FF: from one velocity to another the
// controlword does not change, so nothing else marks when the drive answers.
TEST_P(MotionBlocks, InVelocityOnlyOnceTheDriveRampedToTheNewVelocity) {
    power_on();
    h.link.downloads_act_late = true;
    drive().ramp = 2; // quadcounts per SYNC, each SYNC
    h.set_flag("GoVelocity", true);
    ASSERT_TRUE(cycle_until("Velocity.InVelocity"));
    EXPECT_EQ(drive().velocity, -10);
    h.set_flag("GoVelocity2", true);
    ASSERT_TRUE(cycle_until("Velocity2.InVelocity"));
    EXPECT_TRUE(h.flag("Velocity.CommandAborted"));
    EXPECT_EQ(drive().velocity, 20);
}

TEST_P(MotionBlocks, StopHoldsTheAxisInStoppingUntilExecuteFalls) {
    power_on();
    h.set_flag("GoVelocity", true);
    ASSERT_TRUE(cycle_until("Velocity.InVelocity"));
    h.set_flag("GoStop", true);
    ASSERT_TRUE(cycle_until("StopIt.Done"));
    EXPECT_EQ(state(), AxisState::Stopping);
    EXPECT_TRUE(h.flag("Velocity.CommandAborted"));
    h.set_flag("Go", true); // refused while Stopping
    h.cycle();
    EXPECT_TRUE(h.flag("Move.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("Move.ErrorID"), 0x1020);
    h.set_flag("Go", false);
    h.set_flag("GoStop", false);
    h.cycle(2);
    EXPECT_EQ(state(), AxisState::Standstill);
    h.set_flag("Go", true);
    ASSERT_TRUE(cycle_until("Move.Done"));
}

TEST_P(MotionBlocks, ADriveFaultLeadsToErrorStopAndOnlyResetLeavesIt) {
    power_on();
    h.set_flag("Go", true);
    h.cycle(4);
    drive().error_code = 0x8611; // following error
    h.cycle(2);
    EXPECT_EQ(state(), AxisState::ErrorStop);
    EXPECT_TRUE(h.flag("Move.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("Move.ErrorID"), 0x1004);
    EXPECT_TRUE(h.flag("Power.Error"));
    h.cycle(2);
    EXPECT_EQ(h.get<std::uint16_t>("AxisError.AxisErrorID"), 0x8611);
    h.set_flag("Go", false);
    h.set_flag("Go2", true); // refused in ErrorStop
    h.cycle();
    EXPECT_EQ(h.get<std::uint16_t>("Move2.ErrorID"), 0x1021);
    h.set_flag("GoReset", true);
    ASSERT_TRUE(cycle_until("ResetIt.Done"));
    EXPECT_EQ(drive().error_code, 0);
    h.cycle(8); // the power request still stands: enabled again
    EXPECT_EQ(state(), AxisState::Standstill);
    EXPECT_FALSE(h.flag("Power.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("AxisError.AxisErrorID"), 0);
}

TEST_P(MotionBlocks, ALostSlaveStopsTheAxisAndFailsTheMove) {
    power_on();
    h.set_flag("Go", true);
    h.cycle(4);
    drive().presence = AxisPresence::Lost;
    h.cycle();
    EXPECT_EQ(state(), AxisState::ErrorStop);
    EXPECT_EQ(h.get<std::uint16_t>("Move.ErrorID"), 0x1003);
    EXPECT_EQ(h.get<std::uint16_t>("AxisError.AxisErrorID"), 0x1003);
    h.set_flag("GoReset", true);
    h.cycle();
    EXPECT_TRUE(h.flag("ResetIt.Error")); // still lost
    h.set_flag("GoReset", false);
    h.cycle();
    drive().presence = AxisPresence::Ready;
    h.set_flag("GoReset", true);
    ASSERT_TRUE(cycle_until("ResetIt.Done"));
    h.cycle(8);
    EXPECT_EQ(state(), AxisState::Standstill);
}

TEST_P(MotionBlocks, HomingSetsTheHomePosition) {
    power_on();
    drive().position = drive().taken_target = 5555;
    h.set_flag("GoHome", true);
    h.cycle();
    EXPECT_EQ(state(), AxisState::Homing);
    ASSERT_TRUE(cycle_until("Home.Done"));
    EXPECT_EQ(drive().position, 77);
    EXPECT_EQ(drive().object(0x6098), 35U);
    EXPECT_EQ(drive().object(0x6060), 6U);
    h.cycle();
    EXPECT_EQ(state(), AxisState::Standstill);
}

TEST_P(MotionBlocks, AModeTheDriveDoesNotConfirmFailsTheMove) {
    power_on();
    drive().refuse_mode = true;
    h.set_flag("Go", true);
    ASSERT_TRUE(cycle_until("Move.Error"));
    EXPECT_EQ(h.get<std::uint16_t>("Move.ErrorID"), 0x1040);
    EXPECT_EQ(drive().position, 0);
}

INSTANTIATE_TEST_SUITE_P(Engines, MotionBlocks,
                         testing::Values(vm::Engine::Interpreter, vm::Engine::Compiled),
                         engine_name);

TEST(MotionBlocksAxes, AnUnknownOrUnassignedAxisIsAnError) {
    MotionHarness h;
    h.start(R"ST(
PROGRAM Main
VAR
  Far : AXIS_REF := (AxisNo := 40);
  Free : AXIS_REF := (AxisNo := 7);
  PowerFar, PowerFree : MC_Power;
  Move : MC_MoveAbsolute;
  ResetFree : MC_Reset;
  StateFar, StateFree : MC_ReadAxisState;
  StatusFree : MC_ReadStatus;
END_VAR
PowerFar(Axis := Far, Enable := TRUE);
PowerFree(Axis := Free, Enable := TRUE);
Move(Axis := Free, Execute := TRUE, Position := 1, Velocity := 1, Acceleration := 1,
     Deceleration := 1);
ResetFree(Axis := Free, Execute := TRUE);
StateFar(Axis := Far, Enable := TRUE);
StateFree(Axis := Free, Enable := TRUE);
StatusFree(Axis := Free, Enable := TRUE);
END_PROGRAM
)ST");
    h.cycle(3);
    EXPECT_EQ(h.get<std::uint16_t>("PowerFar.ErrorID"), 0x1001);
    EXPECT_FALSE(h.flag("PowerFar.Status"));
    EXPECT_EQ(h.get<std::uint16_t>("PowerFree.ErrorID"), 0x1001);
    EXPECT_EQ(h.get<std::uint16_t>("Move.ErrorID"), 0x1001);
    // Every block says the same of an axis the axis table has no slave for.
    for (const char* block : {"ResetFree", "StateFar", "StateFree", "StatusFree"}) {
        EXPECT_TRUE(h.flag(std::string(block) + ".Error")) << block;
        EXPECT_EQ(h.get<std::uint16_t>(std::string(block) + ".ErrorID"), 0x1001) << block;
    }
    EXPECT_FALSE(h.flag("ResetFree.Done"));
    EXPECT_FALSE(h.flag("StateFree.Valid"));
    EXPECT_FALSE(h.flag("StatusFree.Disabled"));
}

} // namespace
} // namespace eposp::plcopen::test
