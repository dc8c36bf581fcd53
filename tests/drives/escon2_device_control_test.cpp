// ESCON2 FW spec 2.2, tables 6 - 8: the shared device control in its ESCON2 variant, transition
// by transition. The ESCON2 has no Refresh / Measure Init (transition 3 calibrates the current
// offset, 4 enables at once) and keeps statusword bit 8 reserved (0).
#include "eposp/drives/motion/device_control.hpp"

#include <functional>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::drives::motion {
namespace {

// Table 8: the controlword low bytes.
constexpr std::uint16_t kShutdown = 0x06;
constexpr std::uint16_t kSwitchOn = 0x07;
constexpr std::uint16_t kDisableOperation = 0x07;
constexpr std::uint16_t kEnableOperation = 0x0F;
constexpr std::uint16_t kDisableVoltage = 0x00;
constexpr std::uint16_t kQuickStop = 0x02;
constexpr std::uint16_t kFaultReset = 0x80;

// Table 6: the statusword bits that are not "x" (0 - 3, 5, 6) and their values per state.
constexpr std::uint16_t kTable6Mask = 0x006F;
constexpr std::uint16_t kNotReadyToSwitchOn = 0x0000;
constexpr std::uint16_t kSwitchOnDisabled = 0x0040;
constexpr std::uint16_t kReadyToSwitchOn = 0x0021;
constexpr std::uint16_t kSwitchedOn = 0x0023;
constexpr std::uint16_t kOperationEnabled = 0x0027;
constexpr std::uint16_t kQuickStopActive = 0x0007;
constexpr std::uint16_t kFaultReactionActive = 0x000F;
constexpr std::uint16_t kFault = 0x0008;

struct Step {
    const char* transition; ///< table 7
    std::function<void(DeviceControl&)> event;
    std::uint16_t statusword; ///< under kTable6Mask, once the transition is done
};

std::function<void(DeviceControl&)> controlword(std::uint16_t value) {
    return [value](DeviceControl& control) {
        control.write_controlword(value);
    };
}

const std::function<void(DeviceControl&)> kFaultOccurs = [](DeviceControl& control) {
    control.fault_occurred(FaultClass::Critical);
};
const std::function<void(DeviceControl&)> kReactionCompleted = [](DeviceControl& control) {
    control.stop_completed();
};

struct Path {
    const char* name;
    std::vector<Step> steps;
};

const std::vector<Path> kPaths = {
    {"EnableAndDisable",
     {{"2", controlword(kShutdown), kReadyToSwitchOn},
      {"3", controlword(kSwitchOn), kSwitchedOn},
      {"4", controlword(kEnableOperation), kOperationEnabled},
      {"5 (slows down)", controlword(kDisableOperation), kOperationEnabled},
      {"5 done", kReactionCompleted, kSwitchedOn},
      {"6", controlword(kShutdown), kReadyToSwitchOn},
      {"3 + 4 (*1)", controlword(kEnableOperation), kOperationEnabled},
      {"8", controlword(kShutdown), kReadyToSwitchOn},
      {"7", controlword(kDisableVoltage), kSwitchOnDisabled}}},
    {"QuickStop",
     {{"2", controlword(kShutdown), kReadyToSwitchOn},
      {"3 + 4", controlword(kEnableOperation), kOperationEnabled},
      {"11", controlword(kQuickStop), kQuickStopActive},
      {"16", controlword(kEnableOperation), kOperationEnabled},
      {"11", controlword(kQuickStop), kQuickStopActive},
      {"12", controlword(kDisableVoltage), kSwitchOnDisabled},
      {"2", controlword(kShutdown), kReadyToSwitchOn},
      {"3", controlword(kSwitchOn), kSwitchedOn},
      {"10", controlword(kQuickStop), kSwitchOnDisabled},
      {"2", controlword(kShutdown), kReadyToSwitchOn},
      {"3 + 4", controlword(kEnableOperation), kOperationEnabled},
      {"9", controlword(kDisableVoltage), kSwitchOnDisabled}}},
    {"Fault",
     {{"2", controlword(kShutdown), kReadyToSwitchOn},
      {"3 + 4", controlword(kEnableOperation), kOperationEnabled},
      {"13", kFaultOccurs, kFaultReactionActive},
      {"14", kReactionCompleted, kFault},
      {"commands are ignored", controlword(kEnableOperation), kFault},
      {"15", controlword(kFaultReset), kSwitchOnDisabled},
      {"2", controlword(kShutdown), kReadyToSwitchOn}}},
};

class Escon2DeviceControl : public ::testing::TestWithParam<Path> {};

TEST_P(Escon2DeviceControl, FollowsTables6To8) {
    DeviceControl control({}, StateMachine::Escon2);
    control.node_reset();
    control.initialise(); // 0
    EXPECT_EQ(control.statusword() & kTable6Mask, kNotReadyToSwitchOn);
    control.initialisation_finished(); // 1
    EXPECT_EQ(control.statusword() & kTable6Mask, kSwitchOnDisabled);
    for (const Step& step : GetParam().steps) {
        SCOPED_TRACE(step.transition);
        step.event(control);
        EXPECT_EQ(control.statusword() & kTable6Mask, step.statusword);
        EXPECT_EQ(control.statusword() & 0x0100, 0) << "bit 8 is reserved (0)";
    }
}

INSTANTIATE_TEST_SUITE_P(Paths, Escon2DeviceControl, ::testing::ValuesIn(kPaths),
                         [](const auto& path) { return std::string(path.param.name); });

// Table 7, transition 4: "Enable the driving function" at once, power applied (bit 4).
TEST(Escon2DeviceControlOutputs, OperationEnabledPowersTheMotorAtOnce) {
    DeviceControl control({}, StateMachine::Escon2);
    control.node_reset();
    control.initialise();
    control.initialisation_finished();
    control.write_controlword(kShutdown);
    control.write_controlword(kEnableOperation);
    EXPECT_EQ(control.state(), DriveState::OperationEnable);
    EXPECT_TRUE(control.outputs().power_stage_on);
    EXPECT_TRUE(control.outputs().drive_function_enabled);
    EXPECT_EQ(control.statusword() & 0x0010, 0x0010) << "voltage enabled";
}

// 7.1 "f": a quick stop ramp with the power stage on (fault reaction active 0x1F), then Fault.
TEST(Escon2DeviceControlOutputs, DeviceFaultQuickStopsBeforeFault) {
    DeviceControl control({}, StateMachine::Escon2);
    control.node_reset();
    control.initialise();
    control.initialisation_finished();
    control.write_controlword(kShutdown);
    control.write_controlword(kEnableOperation);
    control.fault_occurred(FaultClass::Device);
    EXPECT_EQ(control.outputs().ramp, StopRamp::QuickStop);
    EXPECT_EQ(control.statusword() & 0x007F, 0x001F);
    control.stop_completed();
    EXPECT_EQ(control.statusword() & 0x007F, kFault);
    EXPECT_FALSE(control.outputs().power_stage_on);
}

// The EPOS2 variant keeps its Refresh: nothing of it changed.
TEST(Escon2DeviceControlOutputs, Epos2StillPassesRefresh) {
    DeviceControl control;
    control.node_reset();
    control.initialise();
    control.initialisation_finished();
    control.write_controlword(kShutdown);
    control.write_controlword(kEnableOperation);
    EXPECT_EQ(control.state(), DriveState::Refresh);
    EXPECT_EQ(control.statusword() & 0x0100, 0x0100);
}

} // namespace
} // namespace eposp::drives::motion
