// `eposp test` with the machine in the loop: faults injected from ST (InjectDriveError,
// InjectHeartbeatLoss, …) and a suite that names its own network file.
#include "../eposp_command.hpp"

#include <gmock/gmock.h>

namespace eposp::device {
namespace {

using ::testing::HasSubstr;

// Runs a suite on axis 0 (the internal EPOS2 of the default device), which it powers and whose
// state and error it reads, with `variables` declared besides and `body` as its tests; expects
// its one test to pass.
void expect_axis_suite_passes(const std::string& name, const std::string& variables,
                              const std::string& body) {
    const std::string suite = write_source(name + ".st", "FUNCTION_BLOCK " + name + R"(
VAR
    Axis : AXIS_REF := (AxisNo := 0);
    Power : MC_Power;
    Status : MC_ReadStatus;
    AxisError : MC_ReadAxisError;
)" + variables + R"(END_VAR
    Power(Axis := Axis, Enable := TRUE);
    Status(Axis := Axis, Enable := TRUE);
    AxisError(Axis := Axis, Enable := TRUE);
)" + body + "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("1 passed, 0 failed"));
}

TEST(EpospTestFaults, AnInjectedDriveErrorPutsTheAxisInErrorStopWithItsCode) {
    expect_axis_suite_passes("DriveErrorSuite", "", R"(
    TEST('OverCurrentStopsTheAxis');
    IF WAIT_UNTIL(Power.Status, T#2s) THEN
        InjectDriveError(Axis := 0, ErrorCode := 16#2310);
        IF WAIT_UNTIL(Status.ErrorStop AND AxisError.AxisErrorID <> 0, T#1s) THEN
            AssertEquals_WORD(16#2310, AxisError.AxisErrorID, 'the drive error');
            TEST_FINISHED();
        END_IF
    END_IF
)");
}

TEST(EpospTestFaults, AnInjectedHeartbeatLossLosesTheAxisAndARestoreBringsItBack) {
    expect_axis_suite_passes("HeartbeatSuite", "    Reset : MC_Reset;\n    Restored : BOOL;\n", R"(
    Reset(Axis := Axis, Execute := Restored);
    TEST('LostThenBack');
    IF WAIT_UNTIL(Power.Status, T#2s) THEN
        InjectHeartbeatLoss(Axis := 0);
        IF WAIT_UNTIL(Status.ErrorStop, T#1s) THEN
            RestoreHeartbeat(Axis := 0);
            Restored := ADVANCE_TIME(T#200ms); (* booted again: then MC_Reset *)
            IF WAIT_UNTIL(Status.Standstill, T#3s) THEN
                TEST_FINISHED();
            END_IF
        END_IF
    END_IF
)");
}

TEST(EpospTestFaults, ATrippedLimitSwitchInTheExecutionMaskPutsTheAxisInErrorStop) {
    expect_axis_suite_passes("LimitSwitchSuite", "    Mask : MC_WriteParameter;\n", R"(
    (* 0x2071 sub 4, the execution mask: both limit switches stop the drive (8.2.57). *)
    Mask(Axis := Axis, Execute := TRUE, ParameterNumber := 16#207104, Value := 3);
    TEST('PositiveLimitSwitch');
    IF WAIT_UNTIL(Power.Status AND Mask.Done, T#2s) THEN
        InjectLimitSwitch(Axis := 0, Positive := TRUE, Pressed := TRUE);
        IF WAIT_UNTIL(Status.ErrorStop AND AxisError.AxisErrorID <> 0, T#1s) THEN
            AssertEquals_WORD(16#FF07, AxisError.AxisErrorID, 'the positive limit error');
            TEST_FINISHED();
        END_IF
    END_IF
)");
}

TEST(EpospTestFaults, DroppedStatuswordFramesLoseTheAxis) {
    expect_axis_suite_passes("PdoFaultSuite", "", R"(
    TEST('TwentyTpdosDropped');
    IF WAIT_UNTIL(Power.Status, T#2s) THEN
        InjectPdoFault(Axis := 0, Pdo := 1, FromDrive := TRUE, Frames := 20, Drop := TRUE);
        IF WAIT_UNTIL(Status.ErrorStop, T#1s) THEN
            TEST_FINISHED();
        END_IF
    END_IF
)");
}

TEST(EpospTestFaults, AFaultTheDeviceRefusesFailsTheTestWithTheReason) {
    const std::string suite = write_source("refused_test.st", R"(
FUNCTION_BLOCK RefusedSuite
    TEST('NoSuchAxis');
    InjectDriveError(Axis := 7, ErrorCode := 16#2310);
    TEST_FINISHED();

    TEST('NoSuchError');
    InjectDriveError(Axis := 0, ErrorCode := 16#1234);
    TEST_FINISHED();
END_FUNCTION_BLOCK
)");
    const auto result = eposp("test " + suite);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr(suite + ":4: RefusedSuite.NoSuchAxis: InjectDriveError: "
                                                 "axis 7 has no slave"));
    EXPECT_THAT(result.output, HasSubstr(suite + ":8: RefusedSuite.NoSuchError: InjectDriveError: "
                                                 "0x1234 is not an EPOS2 error code"));
    EXPECT_THAT(result.output, HasSubstr("0 passed, 2 failed"));
}

TEST(EpospTestNetwork, ASuiteRunsOnTheNetworkItsAttributeNamesBesideItsFile) {
    write_source("two_axes.yaml", R"(sync_period: 2ms
slaves:
  - {node: 1, port: internal, axis: 0, heartbeat: 100ms}
  - {node: 2, axis: 1, heartbeat: 100ms}
)");
    const std::string suite = write_source("network_test.st", R"(
{attribute 'network' := 'two_axes.yaml'}
FUNCTION_BLOCK OnTwoAxes
VAR
    Axis : AXIS_REF := (AxisNo := 1);
    Power : MC_Power;
    Started : TIME;
    Cycles : INT;
END_VAR
    Power(Axis := Axis, Enable := TRUE);
    Cycles := Cycles + 1;
    TEST('AxisOneIsThere');
    IF WAIT_UNTIL(Power.Status, T#2s) THEN
        TEST_FINISHED();
    END_IF
    TEST('TheTaskRunsEverySyncPeriod');
    IF ADVANCE_TIME(T#100ms) THEN
        AssertEquals_INT(51, Cycles, 'cycles in 100 ms at 2 ms');
        TEST_FINISHED();
    END_IF
END_FUNCTION_BLOCK

FUNCTION_BLOCK OnTheDefaultDevice
VAR
    Axis : AXIS_REF := (AxisNo := 1);
    Power : MC_Power;
END_VAR
    Power(Axis := Axis, Enable := TRUE);
    TEST('HasNoAxisOne');
    IF WAIT_UNTIL(Power.Error, T#1s) THEN
        TEST_FINISHED();
    END_IF
END_FUNCTION_BLOCK
)");
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("3 passed, 0 failed"));
}

TEST(EpospTestNetwork, AMissingNetworkOfAnAttributeFailsItsSuite) {
    const std::string suite = write_source("missing_network_test.st", R"(
{attribute 'network' := 'nowhere.yaml'}
FUNCTION_BLOCK Nowhere
    TEST('Never');
    TEST_FINISHED();
END_FUNCTION_BLOCK
)");
    const auto result = eposp("test " + suite);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr(suite + ":3: Nowhere: its network attribute: "));
    EXPECT_THAT(result.output, HasSubstr("nowhere.yaml"));
}

TEST(EpospTestNetwork, AMalformedNetworkAttributeIsAnErrorWithItsLine) {
    const std::string suite = write_source("bad_attribute_test.st", R"(
{attribute 'network' := ''}
FUNCTION_BLOCK Bad
    TEST('Never');
    TEST_FINISHED();
END_FUNCTION_BLOCK
)");
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(suite + ":2: error: a network attribute reads"));
}

} // namespace
} // namespace eposp::device
