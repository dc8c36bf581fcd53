#include "eposp/drives/motion/device_control.hpp"

#include <functional>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::drives::motion {
namespace {

// Controlword low bytes of EPOS2 FW spec table 3-6.
constexpr std::uint16_t kShutdown = 0x06;
constexpr std::uint16_t kSwitchOn = 0x07;
constexpr std::uint16_t kDisableOperation = 0x07;
constexpr std::uint16_t kEnableOperation = 0x0F;
constexpr std::uint16_t kDisableVoltage = 0x00;
constexpr std::uint16_t kQuickStop = 0x02;
constexpr std::uint16_t kFaultReset = 0x80;

/// Drives a fresh machine into `target` along the usual path of figure 3-3.
void reach(DeviceControl& control, DriveState target) {
    const auto at = [&] {
        return control.state() == target;
    };
    control.node_reset();
    if (at())
        return;
    control.initialise();
    if (at())
        return;
    control.initialisation_finished();
    if (at())
        return;
    if (target == DriveState::FaultReactionActiveDisabled || target == DriveState::Fault) {
        control.fault_occurred(FaultClass::Device);
        if (!at())
            control.stop_completed();
        return;
    }
    control.write_controlword(kShutdown);
    if (at())
        return;
    control.write_controlword(kSwitchOn);
    if (at())
        return;
    control.write_controlword(kEnableOperation);
    if (at())
        return;
    control.refresh_finished();
    if (at())
        return;
    control.measure_init_finished();
    if (at())
        return;
    if (target == DriveState::QuickStopActive) {
        control.write_controlword(kQuickStop);
    } else if (target == DriveState::FaultReactionActiveEnabled) {
        control.fault_occurred(FaultClass::Device);
    }
}

struct TransitionRow {
    std::string name;
    DriveState from;
    std::function<void(DeviceControl&)> event;
    DriveState to;
    std::uint16_t statusword; // the state bits of table 3-4 after the transition
    OptionCodes codes = {};
};

void PrintTo(const TransitionRow& row, std::ostream* out) {
    *out << row.name;
}

std::function<void(DeviceControl&)> controlword(std::uint16_t value) {
    return [value](DeviceControl& control) {
        control.write_controlword(value);
    };
}

const OptionCodes kDisableAtOnce{3, 0, 0, 2};

// Every transition of EPOS2 FW spec table 3-5.
const std::vector<TransitionRow> kTransitions = {
    {"T0_ResetInitialises", DriveState::Start, [](auto& c) { c.initialise(); },
     DriveState::NotReadyToSwitchOn, 0x0100},
    {"T1_InitialisedSwitchOnDisabled", DriveState::NotReadyToSwitchOn,
     [](auto& c) { c.initialisation_finished(); }, DriveState::SwitchOnDisabled, 0x0140},
    {"T2_Shutdown", DriveState::SwitchOnDisabled, controlword(kShutdown),
     DriveState::ReadyToSwitchOn, 0x0121},
    {"T3_SwitchOn", DriveState::ReadyToSwitchOn, controlword(kSwitchOn), DriveState::SwitchedOn,
     0x0123},
    {"T3_4_SwitchOnAndEnableOperationRefreshes", DriveState::ReadyToSwitchOn,
     controlword(kEnableOperation), DriveState::Refresh, 0x4123},
    {"T4_EnableOperationRefreshes", DriveState::SwitchedOn, controlword(kEnableOperation),
     DriveState::Refresh, 0x4123},
    {"T20_RefreshFinished", DriveState::Refresh, [](auto& c) { c.refresh_finished(); },
     DriveState::MeasureInit, 0x4133},
    {"T21_MeasureInitFinished", DriveState::MeasureInit, [](auto& c) { c.measure_init_finished(); },
     DriveState::OperationEnable, 0x0137},
    {"T5_DisableOperationAtOnce", DriveState::OperationEnable, controlword(kDisableOperation),
     DriveState::SwitchedOn, 0x0123, kDisableAtOnce},
    {"T5_DisableOperationAfterSlowDown", DriveState::OperationEnable,
     [](auto& c) {
         c.write_controlword(kDisableOperation);
         c.stop_completed();
     },
     DriveState::SwitchedOn, 0x0123},
    {"T6_Shutdown", DriveState::SwitchedOn, controlword(kShutdown), DriveState::ReadyToSwitchOn,
     0x0121},
    {"T7_DisableVoltage", DriveState::ReadyToSwitchOn, controlword(kDisableVoltage),
     DriveState::SwitchOnDisabled, 0x0140},
    {"T7_QuickStop", DriveState::ReadyToSwitchOn, controlword(kQuickStop),
     DriveState::SwitchOnDisabled, 0x0140},
    {"T8_ShutdownAtOnce", DriveState::OperationEnable, controlword(kShutdown),
     DriveState::ReadyToSwitchOn, 0x0121},
    {"T8_ShutdownAfterSlowDown", DriveState::OperationEnable,
     [](auto& c) {
         c.write_controlword(kShutdown);
         c.stop_completed();
     },
     DriveState::ReadyToSwitchOn, 0x0121, OptionCodes{3, 1, 1, 2}},
    {"T9_DisableVoltage", DriveState::OperationEnable, controlword(kDisableVoltage),
     DriveState::SwitchOnDisabled, 0x0140},
    {"T10_DisableVoltage", DriveState::SwitchedOn, controlword(kDisableVoltage),
     DriveState::SwitchOnDisabled, 0x0140},
    {"T10_QuickStop", DriveState::SwitchedOn, controlword(kQuickStop), DriveState::SwitchOnDisabled,
     0x0140},
    {"T11_QuickStop", DriveState::OperationEnable, controlword(kQuickStop),
     DriveState::QuickStopActive, 0x0117},
    {"T12_DisableVoltage", DriveState::QuickStopActive, controlword(kDisableVoltage),
     DriveState::SwitchOnDisabled, 0x0140},
    {"T13_FaultWhileSwitchOnDisabled", DriveState::SwitchOnDisabled,
     [](auto& c) { c.fault_occurred(FaultClass::Device); }, DriveState::FaultReactionActiveDisabled,
     0x010F},
    {"T13_FaultWhileSwitchedOn", DriveState::SwitchedOn,
     [](auto& c) { c.fault_occurred(FaultClass::Critical); },
     DriveState::FaultReactionActiveDisabled, 0x010F},
    {"T14_FaultReactionCompleted", DriveState::FaultReactionActiveDisabled,
     [](auto& c) { c.stop_completed(); }, DriveState::Fault, 0x0108},
    {"T15_FaultReset", DriveState::Fault, controlword(kFaultReset), DriveState::SwitchOnDisabled,
     0x0140},
    {"T16_EnableOperation", DriveState::QuickStopActive, controlword(kEnableOperation),
     DriveState::OperationEnable, 0x0137},
    {"T17_FaultWhileOperationEnabled", DriveState::OperationEnable,
     [](auto& c) { c.fault_occurred(FaultClass::Device); }, DriveState::FaultReactionActiveEnabled,
     0x011F},
    {"T17_FaultWhileQuickStopActive", DriveState::QuickStopActive,
     [](auto& c) { c.fault_occurred(FaultClass::Communication); },
     DriveState::FaultReactionActiveEnabled, 0x011F},
    {"T18_FaultReactionCompleted", DriveState::FaultReactionActiveEnabled,
     [](auto& c) { c.stop_completed(); }, DriveState::Fault, 0x0108},
    {"T19_NodeResetFromOperationEnable", DriveState::OperationEnable,
     [](auto& c) { c.node_reset(); }, DriveState::Start, 0x0000},
    {"T19_NodeResetFromFault", DriveState::Fault, [](auto& c) { c.node_reset(); },
     DriveState::Start, 0x0000},
};

class DeviceControlTransition : public ::testing::TestWithParam<TransitionRow> {};

TEST_P(DeviceControlTransition, ReachesStateWithStatuswordOfTable3_4) {
    const TransitionRow& row = GetParam();
    DeviceControl control(row.codes);
    reach(control, row.from);
    ASSERT_EQ(control.state(), row.from) << to_string(control.state());
    row.event(control);
    EXPECT_EQ(control.state(), row.to) << to_string(control.state());
    EXPECT_EQ(control.statusword() & kStateBitsMask, row.statusword);
    EXPECT_EQ(state_bits(row.to), row.statusword);
}

INSTANTIATE_TEST_SUITE_P(Table3_5, DeviceControlTransition, ::testing::ValuesIn(kTransitions),
                         [](const auto& row) { return row.param.name; });

struct CommandRow {
    std::uint16_t controlword;
    DeviceCommand command;
};

// Table 3-6, with the don't-care bits of each pattern set both ways.
TEST(DeviceControl, ControlwordPatternsDecodeAsTable3_6) {
    const std::vector<CommandRow> rows = {
        {0x06, DeviceCommand::Shutdown},       {0x0E, DeviceCommand::Shutdown},
        {0x07, DeviceCommand::SwitchOn},       {0x0F, DeviceCommand::EnableOperation},
        {0x00, DeviceCommand::DisableVoltage}, {0x0D, DeviceCommand::DisableVoltage},
        {0x05, DeviceCommand::DisableVoltage}, {0x02, DeviceCommand::QuickStop},
        {0x0B, DeviceCommand::QuickStop},      {0x7F, DeviceCommand::EnableOperation},
        {0x77, DeviceCommand::SwitchOn},
    };
    for (const CommandRow& row : rows) {
        EXPECT_EQ(decode_device_command(row.controlword), row.command) << row.controlword;
    }
}

TEST(DeviceControl, FaultResetActsOnlyOnRisingEdge) {
    DeviceControl control;
    reach(control, DriveState::Fault);
    control.write_controlword(kFaultReset);
    ASSERT_EQ(control.state(), DriveState::SwitchOnDisabled);
    control.fault_occurred(FaultClass::Device);
    control.stop_completed();
    control.write_controlword(kFaultReset); // bit 7 still high: no edge
    EXPECT_EQ(control.state(), DriveState::Fault);
    control.write_controlword(0x00);
    control.write_controlword(kFaultReset);
    EXPECT_EQ(control.state(), DriveState::SwitchOnDisabled);
}

TEST(DeviceControl, FaultResetRefusedWhileFaultConditionPersists) {
    DeviceControl control;
    reach(control, DriveState::Fault);
    control.set_fault_condition_present(true);
    control.write_controlword(kFaultReset);
    EXPECT_EQ(control.state(), DriveState::Fault);
    control.set_fault_condition_present(false);
    control.write_controlword(0x00);
    control.write_controlword(kFaultReset);
    EXPECT_EQ(control.state(), DriveState::SwitchOnDisabled);
}

TEST(DeviceControl, CommandsWithFaultResetBitHeldAreIgnored) {
    DeviceControl control;
    reach(control, DriveState::SwitchOnDisabled);
    control.write_controlword(kFaultReset);
    control.write_controlword(kFaultReset | kShutdown);
    EXPECT_EQ(control.state(), DriveState::SwitchOnDisabled);
    control.write_controlword(kShutdown);
    EXPECT_EQ(control.state(), DriveState::ReadyToSwitchOn);
}

TEST(DeviceControl, CommandsOutsideTheTableLeaveTheStateAlone) {
    DeviceControl control;
    reach(control, DriveState::SwitchOnDisabled);
    control.write_controlword(kEnableOperation);
    EXPECT_EQ(control.state(), DriveState::SwitchOnDisabled);
    reach(control, DriveState::Fault);
    control.write_controlword(kShutdown);
    EXPECT_EQ(control.state(), DriveState::Fault);
}

TEST(DeviceControl, CommandDuringRefreshIsAppliedOnceOperationEnabled) {
    DeviceControl control;
    reach(control, DriveState::Refresh);
    control.write_controlword(kQuickStop);
    EXPECT_EQ(control.state(), DriveState::Refresh);
    control.refresh_finished();
    control.measure_init_finished();
    EXPECT_EQ(control.state(), DriveState::QuickStopActive);
}

TEST(DeviceControl, SlowDownKeepsOperationEnableUntilStopped) {
    DeviceControl control; // 0x605C defaults to 1: slow down
    reach(control, DriveState::OperationEnable);
    control.write_controlword(kDisableOperation);
    EXPECT_EQ(control.state(), DriveState::OperationEnable);
    EXPECT_EQ(control.outputs(), (DriveOutputs{true, true, StopRamp::SlowDown}));
    control.stop_completed();
    EXPECT_EQ(control.state(), DriveState::SwitchedOn);
    EXPECT_EQ(control.outputs(), DriveOutputs{});
}

TEST(DeviceControl, QuickStopActiveRampsWithQuickStopDeceleration) {
    DeviceControl control;
    reach(control, DriveState::QuickStopActive);
    EXPECT_EQ(control.outputs(), (DriveOutputs{true, true, StopRamp::QuickStop}));
    control.stop_completed(); // EPOS2 stays in Quickstop Active, holding, until commanded
    EXPECT_EQ(control.state(), DriveState::QuickStopActive);
}

TEST(DeviceControl, PowerStageFollowsTheState) {
    DeviceControl control;
    reach(control, DriveState::Refresh);
    EXPECT_FALSE(control.outputs().power_stage_on);
    control.refresh_finished();
    EXPECT_EQ(control.outputs(), (DriveOutputs{true, false, StopRamp::None}));
    control.measure_init_finished();
    EXPECT_EQ(control.outputs(), (DriveOutputs{true, true, StopRamp::None}));
}

TEST(DeviceControl, OutputsOfEveryState) {
    // Power stage per statusword bit 4 of table 3-4; drive function only where enabled.
    const std::vector<std::pair<DriveState, DriveOutputs>> rows = {
        {DriveState::Start, {}},
        {DriveState::NotReadyToSwitchOn, {}},
        {DriveState::SwitchOnDisabled, {}},
        {DriveState::ReadyToSwitchOn, {}},
        {DriveState::SwitchedOn, {}},
        {DriveState::Refresh, {}},
        {DriveState::MeasureInit, {true, false, StopRamp::None}},
        {DriveState::OperationEnable, {true, true, StopRamp::None}},
        {DriveState::QuickStopActive, {true, true, StopRamp::QuickStop}},
        {DriveState::FaultReactionActiveDisabled, {}},
        {DriveState::FaultReactionActiveEnabled, {true, true, StopRamp::QuickStop}},
        {DriveState::Fault, {}},
    };
    for (const auto& [state, outputs] : rows) {
        DeviceControl control;
        reach(control, state);
        ASSERT_EQ(control.state(), state);
        EXPECT_EQ(control.outputs(), outputs) << to_string(state);
        EXPECT_EQ(control.outputs().power_stage_on, (state_bits(state) & 0x10) != 0)
            << to_string(state);
    }
}

struct ReactionRow {
    std::string name;
    FaultClass fault_class;
    OptionCodes codes;
    DriveOutputs outputs; // during Fault Reaction Active (enabled)
};

void PrintTo(const ReactionRow& row, std::ostream* out) {
    *out << row.name;
}

class DeviceControlFaultReaction : public ::testing::TestWithParam<ReactionRow> {};

TEST_P(DeviceControlFaultReaction, FollowsOptionCode) {
    const ReactionRow& row = GetParam();
    DeviceControl control(row.codes);
    reach(control, DriveState::OperationEnable);
    control.fault_occurred(row.fault_class);
    EXPECT_EQ(control.state(), DriveState::FaultReactionActiveEnabled);
    EXPECT_EQ(control.outputs(), row.outputs);
    control.stop_completed();
    EXPECT_EQ(control.state(), DriveState::Fault);
}

// 0x605E (8.2.89), 0x6007 (8.2.84) and the "d" errors of 4.2.1.
INSTANTIATE_TEST_SUITE_P(
    OptionCodes, DeviceControlFaultReaction,
    ::testing::Values(
        ReactionRow{"FaultReaction0Disables", FaultClass::Device, {3, 0, 1, 0}, {}},
        ReactionRow{"FaultReaction1SlowsDown",
                    FaultClass::Device,
                    {3, 0, 1, 1},
                    {true, true, StopRamp::SlowDown}},
        ReactionRow{"FaultReaction2QuickStops",
                    FaultClass::Device,
                    {3, 0, 1, 2},
                    {true, true, StopRamp::QuickStop}},
        ReactionRow{"AbortConnection2DisablesVoltage", FaultClass::Communication, {2, 0, 1, 2}, {}},
        ReactionRow{"AbortConnection3QuickStops",
                    FaultClass::Communication,
                    {3, 0, 1, 0},
                    {true, true, StopRamp::QuickStop}},
        ReactionRow{"CriticalAlwaysDisables", FaultClass::Critical, {3, 0, 1, 2}, {}}),
    [](const auto& row) { return row.param.name; });

TEST(DeviceControl, SignalOnlyReactionSetsWarningWithoutStateChange) {
    for (const auto& [fault_class, codes] :
         {std::pair{FaultClass::Device, OptionCodes{3, 0, 1, -1}},
          std::pair{FaultClass::Communication, OptionCodes{1, 0, 1, 2}}}) {
        DeviceControl control(codes);
        reach(control, DriveState::OperationEnable);
        control.fault_occurred(fault_class);
        EXPECT_EQ(control.state(), DriveState::OperationEnable);
        EXPECT_EQ(control.statusword(), 0x0137 | kWarningBit);
        control.write_controlword(kFaultReset);
        EXPECT_EQ(control.statusword(), 0x0137);
    }
}

} // namespace
} // namespace eposp::drives::motion
