// EPOS2 FW spec 3.2, tables 3-4 to 3-6 on the running drive, as a master sees them: each
// controlword of table 3-6 by RPDO, then the statusword (table 3-4) by SDO. The transitions of
// the fault path (13, 14, 15, 17, 18) are in epos2_drive_errors_test.cpp; the pure state
// machine is table-tested in motion_device_control_test.cpp.
#include "epos2_bus_fixture.hpp"

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;

constexpr std::uint16_t kDisableVoltage = 0x0000;
constexpr std::uint16_t kQuickStop = 0x0002;
constexpr std::uint16_t kDisableOperation = 0x0007;
// Table 3-4: the bits that are not "x" (0-6, 8, 14).
constexpr std::uint16_t kTable3_4Mask = 0x417F;
constexpr std::uint16_t kSwitchOnDisabledBits = 0x0140;
constexpr std::uint16_t kReadyToSwitchOnBits = 0x0121;
constexpr std::uint16_t kSwitchedOnBits = 0x0123;
constexpr std::uint16_t kOperationEnableBits = 0x0137;
constexpr std::uint16_t kQuickStopActiveBits = 0x0117;

struct Step {
    const char* transition; ///< table 3-5
    std::uint16_t controlword;
    std::uint16_t statusword; ///< under kTable3_4Mask, once the transition is done
};

struct Path {
    const char* name;
    std::vector<Step> steps;
};

const Path kPaths[] = {
    {"EnableDisableOperationAndBack",
     {{"2", kShutdown, kReadyToSwitchOnBits},
      {"3", kSwitchOn, kSwitchedOnBits},
      {"4 (Refresh, Measure Init)", kEnableOperation, kOperationEnableBits},
      {"5", kDisableOperation, kSwitchedOnBits},
      {"4", kEnableOperation, kOperationEnableBits},
      {"8", kShutdown, kReadyToSwitchOnBits},
      {"7", kDisableVoltage, kSwitchOnDisabledBits}}},
    {"QuickStopAndItsWaysOut",
     {{"2", kShutdown, kReadyToSwitchOnBits},
      {"3", kSwitchOn, kSwitchedOnBits},
      {"4", kEnableOperation, kOperationEnableBits},
      {"11", kQuickStop, kQuickStopActiveBits},
      {"16", kEnableOperation, kOperationEnableBits},
      {"11", kQuickStop, kQuickStopActiveBits},
      {"12", kDisableVoltage, kSwitchOnDisabledBits}}},
    {"DisableVoltageFromEveryPowerState",
     {{"2", kShutdown, kReadyToSwitchOnBits},
      {"3", kSwitchOn, kSwitchedOnBits},
      {"6", kShutdown, kReadyToSwitchOnBits},
      {"3", kSwitchOn, kSwitchedOnBits},
      {"10", kDisableVoltage, kSwitchOnDisabledBits},
      {"2", kShutdown, kReadyToSwitchOnBits},
      {"3", kSwitchOn, kSwitchedOnBits},
      {"4", kEnableOperation, kOperationEnableBits},
      {"9", kDisableVoltage, kSwitchOnDisabledBits},
      {"2", kShutdown, kReadyToSwitchOnBits},
      {"7 (by quickstop)", kQuickStop, kSwitchOnDisabledBits}}},
};

class Epos2DriveStateMachine : public Epos2DriveOnBus,
                               public ::testing::WithParamInterface<Path> {};

TEST_P(Epos2DriveStateMachine, StatuswordAfterEveryTransitionAsTable3_4) {
    nmt(canopen::NmtCommand::Start);
    ASSERT_EQ(read<std::uint16_t>(0x6041, 0) & kTable3_4Mask, kSwitchOnDisabledBits);
    for (const Step& step : GetParam().steps) {
        controlword(step.controlword);
        run_with_sync(100ms); // slow-down ramps (0x605B / 0x605C = 1) end at rest
        EXPECT_EQ(read<std::uint16_t>(0x6041, 0) & kTable3_4Mask, step.statusword)
            << "transition " << step.transition;
    }
}

INSTANTIATE_TEST_SUITE_P(Table3_5OnTheBus, Epos2DriveStateMachine, ::testing::ValuesIn(kPaths),
                         [](const auto& path) { return std::string(path.param.name); });

} // namespace
} // namespace eposp::drives::epos2

namespace eposp::drives::epos2 {
namespace {

using namespace test;

// EPOS2 FW spec 7.3, figure 7-54 remark *3 and table 7-65: statusword bit 9 (Remote) is TRUE in
// NMT Operational only, read by SDO (which answers in every state but Stopped).
TEST_F(Epos2DriveOnBus, RemoteBitIsSetInNmtOperationalOnly) {
    constexpr std::uint16_t kRemoteBit = 1U << 9;
    EXPECT_EQ(read<std::uint16_t>(0x6041, 0) & kRemoteBit, 0) << "pre-operational after boot";
    nmt(canopen::NmtCommand::Start);
    // Switch On Disabled (0x0140), target reached (bit 10) and Remote.
    EXPECT_EQ(read<std::uint16_t>(0x6041, 0), 0x0540 | kRemoteBit) << "operational";
    nmt(canopen::NmtCommand::EnterPreOperational);
    EXPECT_EQ(read<std::uint16_t>(0x6041, 0) & kRemoteBit, 0) << "pre-operational again";
    nmt(canopen::NmtCommand::Start);
    nmt(canopen::NmtCommand::ResetCommunication);
    EXPECT_EQ(read<std::uint16_t>(0x6041, 0) & kRemoteBit, 0) << "after reset communication";
}

// The remote bit changes with the NMT command, not with the next control period: a SYNC right
// behind the Start command samples it already (TPDO 3: statusword, position).
TEST_F(Epos2DriveOnBus, FirstTpdoInOperationalCarriesTheRemoteBit) {
    write(0x1802, 2, encode(std::uint8_t{1}));
    write(0x1802, 1, encode(std::uint32_t{0x4000'0000 | kTpdo3Id}));
    loop.run_until(core::TimePoint{std::chrono::ceil<std::chrono::milliseconds>(
                       loop.now().time_since_epoch())} +
                   100us); // just after a control period
    master->send(can::Frame::data_frame(
        canopen::kNmtCanId, {static_cast<std::uint8_t>(canopen::NmtCommand::Start), kNode}));
    master->send(can::Frame::data_frame(kSyncId, {}));
    loop.run_for(500us);
    ASSERT_EQ(tpdos.size(), 1U);
    EXPECT_NE(tpdos.front().statusword & (1U << 9), 0U);
}

} // namespace
} // namespace eposp::drives::epos2
