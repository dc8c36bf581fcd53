// Fault injection into a simulated EPOS2 (docs/epos2.md, "Fault injection"): a limit switch held
// from outside and an error of table 4-11 raised on demand, each with what the firmware
// specification makes of it, seen on the bus as a master sees it.
#include "epos2_bus_fixture.hpp"

#include <stdexcept>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;

constexpr std::uint16_t kNegativeLimitBit = 1U << 0; // table 8-87
constexpr std::uint16_t kPositiveLimitBit = 1U << 1;

class Epos2FaultInjection : public Epos2DriveOnBus {
protected:
    /// The EMCY codes the drive sent, in order.
    std::vector<std::uint16_t> emcy_codes() const {
        std::vector<std::uint16_t> codes;
        for (const auto& emcy : emcys) {
            codes.push_back(static_cast<std::uint16_t>(emcy.at(0) | emcy.at(1) << 8));
        }
        return codes;
    }
};

// 8.2.57 / 4.2.27: with the limit switches in the execution mask, a held negative limit switch
// raises 0xFF06 (error register bit 7, "f": the fault reaction, then Fault); once let go, a
// fault reset recovers the drive.
TEST_F(Epos2FaultInjection, HeldNegativeLimitSwitchRaisesFF06AndReleasedItResetsFromFault) {
    write(0x2071, 4, encode(std::uint16_t{0x0003}));
    configure_and_enable(1);
    drive.hold_limit_switch(LimitSwitch::Negative, true);
    run_with_sync(200ms); // the quickstop ramp of 0x605E's default, then the standstill check
    EXPECT_EQ(emcy_codes(), std::vector<std::uint16_t>{0xFF06});
    ASSERT_FALSE(emcys.empty());
    EXPECT_EQ(emcys.front()[2], 0x80);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1) & 0xFFFF, 0xFF06U);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1) & (kNegativeLimitBit | kPositiveLimitBit),
              kNegativeLimitBit);

    drive.hold_limit_switch(LimitSwitch::Negative, false);
    run_with_sync(5ms);
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1) & kNegativeLimitBit, 0);
    controlword(kFaultReset);
    run_with_sync(5ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
}

// Table 8-89: the default execution mask 0x0008 leaves the limit switches out: the held
// positive switch only shows in 0x2071 sub 1, and pressing it again changes nothing.
TEST_F(Epos2FaultInjection, HeldLimitSwitchOutsideTheExecutionMaskIsOnlyDisplayed) {
    configure_and_enable(1);
    drive.hold_limit_switch(LimitSwitch::Positive, true);
    drive.hold_limit_switch(LimitSwitch::Positive, true);
    run_with_sync(20ms);
    EXPECT_TRUE(emcys.empty());
    EXPECT_EQ(drive.state(), motion::DriveState::OperationEnable);
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1) & (kNegativeLimitBit | kPositiveLimitBit),
              kPositiveLimitBit);
}

// 4.1, table 4-11: an injected overcurrent ("d") is its EMCY with register bit 1, one history
// entry and Fault within a control period; raised again while active it is not a new event; a
// fault reset clears it, and the next one is a new entry.
TEST_F(Epos2FaultInjection, RaisedOvercurrentIsOneErrorEventUntilAFaultReset) {
    configure_and_enable(1);
    drive.raise_device_error(0x2310);
    run_with_sync(2ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
    drive.raise_device_error(0x2310);
    run_with_sync(5ms);
    EXPECT_EQ(emcy_codes(), std::vector<std::uint16_t>{0x2310});
    ASSERT_FALSE(emcys.empty());
    EXPECT_EQ(emcys.front()[2], 0x02);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0x02);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 1U);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x2310U);
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);

    controlword(kFaultReset);
    run_with_sync(5ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    drive.raise_device_error(0x2310);
    run_with_sync(5ms);
    EXPECT_EQ(read<std::uint8_t>(0x1003, 0), 2U);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault);
}

TEST_F(Epos2FaultInjection, ACodeTable4_11DoesNotListIsAProgrammingError) {
    EXPECT_THROW(drive.raise_device_error(0x1234), std::invalid_argument);
    EXPECT_THROW(drive.raise_device_error(0x0000), std::invalid_argument);
    run_with_sync(5ms);
    EXPECT_TRUE(emcys.empty());
}

} // namespace
} // namespace eposp::drives::epos2
