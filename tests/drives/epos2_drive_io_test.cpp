// The digital inputs and outputs, position marker, position compare and holding brake of a
// simulated EPOS2 on the CAN-only bench (EPOS2 FW spec 6.3, 6.4, 8.2.56 - 8.2.61, 8.2.72): pins
// driven through Epos2Drive's I/O interface, everything else as a master sees it.
#include "epos2_bus_fixture.hpp"
#include "eposp/drives/epos2/epos2_io.hpp"

#include <optional>
#include <stdexcept>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using motion::DriveState;

constexpr std::uint16_t kQuickStopActive = 0x0007; // table 3-4 under kStateMask
constexpr std::uint16_t kReadyToSwitchOn = 0x0021;
constexpr std::uint16_t kVoltageEnabledBit = 1U << 4;

class Epos2DriveIo : public Epos2DriveOnBus {
protected:
    /// Input 1 carries `function` (table 8-86), shown and executed.
    void input_1_is(std::uint16_t function) {
        write(0x2070, 1, encode(function));
        const auto bit = static_cast<std::uint16_t>(1U << function);
        write(0x2071, 2, encode(static_cast<std::uint16_t>(0xE007 | bit)));
        write(0x2071, 4, encode(static_cast<std::uint16_t>(0x0008 | bit)));
    }
    /// Output 1 carries `function` (table 8-94) under the mask.
    void output_1_is(std::uint16_t function, std::uint16_t polarity = 0) {
        write(0x2079, 1, encode(function));
        write(0x2078, 2, encode(static_cast<std::uint16_t>(1U << function)));
        write(0x2078, 3, encode(polarity));
    }
    std::uint16_t state_bits() const { return tpdos.back().statusword & kStateMask; }
    std::uint16_t emcy_code(std::size_t n) const {
        return static_cast<std::uint16_t>(emcys.at(n).at(0) | emcys.at(n).at(1) << 8);
    }
    /// The first TPDO after `after` whose state bits are `state`.
    std::optional<Tpdo> first_tpdo_in(std::uint16_t state, double after) const {
        for (const Tpdo& tpdo : tpdos) {
            if (tpdo.time > after && (tpdo.statusword & kStateMask) == state) {
                return tpdo;
            }
        }
        return std::nullopt;
    }
};

// 8.2.56: an input driven from outside shows as the functionality 0x2070 gives it (input 1:
// general purpose A by default, table 8-85), from the next control period on.
TEST_F(Epos2DriveIo, OutsideInputShowsAsItsConfiguredFunctionality) {
    drive.set_digital_input(1, true);
    EXPECT_TRUE(drive.digital_input(1));
    run_with_sync(1ms);
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1), 0x8000);
    write(0x2070, 1, encode(std::uint16_t{14})); // general purpose B
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1), 0x4000);
    drive.set_digital_input(1, false);
    run_with_sync(1ms);
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1), 0);
    EXPECT_THROW(drive.set_digital_input(7, true), std::invalid_argument);
}

// Table 8-88: a low-active home switch (input 4) is active while released.
TEST_F(Epos2DriveIo, LowActivePolarityShowsTheReleasedSwitchActive) {
    write(0x2071, 3, encode(std::uint16_t{0x0004}));
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1), 0x0004);
    drive.set_digital_input(4, true);
    run_with_sync(1ms);
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1), 0);
}

// 8.2.57: the mask filters the display only; the execution mask decides the limit error.
TEST_F(Epos2DriveIo, MaskedLimitSwitchIsHiddenButStillExecuted) {
    write(0x2071, 2, encode(std::uint16_t{0x0000}));
    write(0x2071, 4, encode(std::uint16_t{0x0001}));
    configure_and_enable(1);
    drive.set_digital_input(6, true); // the negative limit switch
    run_with_sync(200ms);
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1), 0);
    ASSERT_EQ(emcys.size(), 1U);
    EXPECT_EQ(emcy_code(0), 0xFF06);
    EXPECT_EQ(drive.state(), DriveState::Fault);
}

// Table 8-86 "Quickstop", executed: its rising edge is the Quick Stop command (11).
TEST_F(Epos2DriveIo, ExecutedQuickstopInputStopsIntoQuickstopActive) {
    input_1_is(5);
    configure_and_enable(1);
    drive.set_digital_input(1, true);
    run_with_sync(5ms);
    EXPECT_EQ(state_bits(), kQuickStopActive);
}

TEST_F(Epos2DriveIo, QuickstopInputOutsideTheExecutionMaskIsOnlyDisplayed) {
    write(0x2070, 1, encode(std::uint16_t{5}));
    write(0x2071, 2, encode(std::uint16_t{0xE027}));
    configure_and_enable(1);
    drive.set_digital_input(1, true);
    run_with_sync(5ms);
    EXPECT_EQ(state_bits(), kOperationEnabled);
    EXPECT_EQ(read<std::uint16_t>(0x2071, 1) & 0x0020, 0x0020);
}

// Table 8-86 "Device enable", executed: enables on its rising edge (also out of Fault),
// disables on its falling edge.
TEST_F(Epos2DriveIo, DeviceEnableInputEnablesAndDisablesTheDrive) {
    input_1_is(4);
    configure_and_enable(1);
    controlword(0x0000); // disable voltage: the master leaves it to the input
    run_with_sync(5ms);
    ASSERT_EQ(state_bits(), kSwitchOnDisabled);
    drive.set_digital_input(1, true);
    run_with_sync(10ms);
    EXPECT_EQ(state_bits(), kOperationEnabled);
    drive.set_digital_input(1, false);
    run_with_sync(5ms);
    EXPECT_EQ(state_bits(), kSwitchOnDisabled);

    drive.raise_device_error(0x8611); // following error: Fault after its reaction
    run_with_sync(300ms);
    ASSERT_EQ(state_bits(), kFault);
    drive.set_digital_input(1, true);
    run_with_sync(10ms);
    EXPECT_EQ(state_bits(), kOperationEnabled);
}

// 8.2.59: a general purpose output follows its bit of 0x2078 sub 1 where the mask has it,
// inverted by the polarity; the firmware's bits 0 … 7 do not take a write.
TEST_F(Epos2DriveIo, GeneralPurposeOutputFollowsItsStateUnderMaskAndPolarity) {
    write(0x2078, 1, encode(std::uint16_t{0x80FF}));
    EXPECT_FALSE(drive.digital_output(1)) << "mask 0: the output keeps its level";
    EXPECT_EQ(read<std::uint16_t>(0x2078, 1), 0x8005) << "ready, brake engaged (power off)";
    write(0x2078, 2, encode(std::uint16_t{0x8000}));
    run_with_sync(2ms);
    EXPECT_TRUE(drive.digital_output(1));
    write(0x2078, 3, encode(std::uint16_t{0x8000}));
    run_with_sync(2ms);
    EXPECT_FALSE(drive.digital_output(1));
    EXPECT_THROW((void)drive.digital_output(5), std::invalid_argument);
}

// Table 8-94 "Ready / Fault": active while the device is ready, inactive in Fault.
TEST_F(Epos2DriveIo, ReadyFaultOutputGoesInactiveOnFault) {
    output_1_is(0);
    run_with_sync(2ms);
    EXPECT_TRUE(drive.digital_output(1));
    drive.raise_device_error(0x2310); // overcurrent, "d"
    run_with_sync(5ms);
    EXPECT_FALSE(drive.digital_output(1));
    EXPECT_EQ(read<std::uint16_t>(0x2078, 1) & 0x0001, 0);
}

// 8.2.58: the actual position captured at the marker input's edge of the configured kind.
TEST_F(Epos2DriveIo, PositionMarkerCapturesTheActualPositionAtTheFallingEdge) {
    input_1_is(3);
    write(0x2074, 2, encode(std::uint8_t{2})); // falling edge
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 20000);
    run_with_sync(50ms);
    drive.set_digital_input(1, true);
    run_with_sync(50ms);
    EXPECT_EQ(read<std::uint16_t>(0x2074, 4), 0) << "a rising edge does not capture";
    drive.set_digital_input(1, false);
    run_with_sync(1ms);
    const std::int32_t at_edge = tpdos.back().position;
    run_with_sync(20ms);
    EXPECT_EQ(read<std::uint16_t>(0x2074, 4), 1);
    EXPECT_NEAR(read<std::int32_t>(0x2074, 1), at_edge, 200);
    EXPECT_GT(read<std::int32_t>(0x2074, 1), 1000);

    write(0x2074, 4, encode(std::uint16_t{0})); // clears
    EXPECT_EQ(read<std::int32_t>(0x2074, 1), 0);
}

// Table 8-91 "Single & Stop": the capture stops the motion with the slow-down ramp.
TEST_F(Epos2DriveIo, PositionMarkerSingleAndStopHaltsTheMotion) {
    input_1_is(3);
    write(0x2074, 3, encode(std::uint8_t{3}));
    write(0x60FF, 0, encode(std::int32_t{1000}));
    configure_and_enable(3);
    run_with_sync(200ms);
    drive.set_digital_input(1, true);
    run_with_sync(300ms);
    EXPECT_EQ(read<std::uint16_t>(0x2074, 4), 1);
    EXPECT_NEAR(read<std::int32_t>(0x606C, 0), 0, 30);
    EXPECT_EQ(state_bits(), kOperationEnabled);
}

// 8.2.61: single position mode, both directions: one pulse on output 1 in the period the actual
// position passes the reference.
TEST_F(Epos2DriveIo, PositionCompareOutputPulsesWhereThePositionPassesTheReference) {
    output_1_is(1);
    write(0x207A, 2, encode(std::int32_t{5000}));
    write(0x207A, 1, encode(std::uint16_t{0x0041})); // enable, single, both directions
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 10000);
    std::vector<std::int64_t> high_at;
    std::int64_t before = drive.axis().position_actual();
    for (int ms = 0; ms < 600; ++ms) {
        loop.run_for(1ms);
        const std::int64_t position = drive.axis().position_actual();
        if (drive.digital_output(1)) {
            EXPECT_LT(before, 5000);
            EXPECT_GE(position, 5000);
            high_at.push_back(position);
        }
        before = position;
    }
    EXPECT_EQ(high_at.size(), 1U);
    EXPECT_NEAR(static_cast<double>(before), 10000, 5);
}

// 8.2.72: with a brake output, Operation Enable is reported the fall time after the power stage
// came on (Measure Init); the brake's output is released (low active: pin high) meanwhile.
TEST_F(Epos2DriveIo, BrakeFallTimeDelaysOperationEnabled) {
    write(0x2100, 2, encode(std::uint16_t{50}));
    output_1_is(2, /*polarity=*/0x0004);
    write(0x1802, 2, encode(std::uint8_t{1}));
    write(0x1802, 1, encode(std::uint32_t{0x4000'0000 | kTpdo3Id}));
    nmt(canopen::NmtCommand::Start);
    for (const std::uint16_t word : {kShutdown, kEnableOperation}) {
        controlword(word);
        run_with_sync(10ms);
    }
    EXPECT_EQ(drive.state(), DriveState::MeasureInit) << "power stage on, brake letting go";
    const std::optional<Tpdo> power_on = first_tpdo_with(kVoltageEnabledBit, 0);
    ASSERT_TRUE(power_on);
    EXPECT_TRUE(drive.digital_output(1)) << "brake powered: released";
    run_with_sync(50ms);
    const std::optional<Tpdo> enabled = first_tpdo_in(kOperationEnabled, 0);
    ASSERT_TRUE(enabled);
    EXPECT_NEAR(enabled->time - power_on->time, 0.050, 0.0025);
}

// 8.2.72: after a shutdown at rest the brake engages at once and the power stage holds the axis
// for the rise time; the state is Ready to Switch On at once.
TEST_F(Epos2DriveIo, BrakeRiseTimeKeepsThePowerStageOnAfterShutdown) {
    write(0x2100, 1, encode(std::uint16_t{40}));
    write(0x2100, 2, encode(std::uint16_t{0}));
    output_1_is(2, 0x0004);
    configure_and_enable(1);
    run_with_sync(100ms);
    ASSERT_EQ(state_bits(), kOperationEnabled);
    controlword(kShutdown);
    run_with_sync(2ms);
    EXPECT_EQ(state_bits(), kReadyToSwitchOn);
    EXPECT_FALSE(drive.digital_output(1)) << "brake unpowered: engaged";
    int powered_ms = 0;
    while (drive.axis().mode() != plant::ControlMode::PowerOff && powered_ms < 200) {
        run_with_sync(1ms);
        ++powered_ms;
    }
    EXPECT_NEAR(powered_ms, 40, 2);
}

// 8.2.60: the brake output changes in a power-disabled state only (0x08000022 otherwise).
TEST_F(Epos2DriveIo, BrakeOutputChangeIsRefusedWhileThePowerStageIsOn) {
    configure_and_enable(1);
    std::optional<AbortCode> result;
    client.download(kNode, 0x2079, 1, encode(std::uint16_t{2}),
                    [&result](AbortCode code) { result = code; });
    loop.run_for(20ms);
    EXPECT_EQ(result, AbortCode::DeviceState);
    write(0x2079, 1, encode(std::uint16_t{14})); // general purpose B: no brake involved
    controlword(kShutdown);
    run_with_sync(5ms);
    write(0x2079, 1, encode(std::uint16_t{2}));
}

// The first control period compares no passage: the position before it is unknown, not 0.
TEST(Epos2Io, FirstPeriodPassesNoComparePosition) {
    Epos2Dictionary dictionary{Epos2DictionaryConfig{}};
    canopen::ObjectDictionary& od = dictionary.objects();
    od.set_as(0x2079, 1, std::uint16_t{1});      // output 1: position compare
    od.set_as(0x2078, 2, std::uint16_t{0x0002}); // under the mask
    od.set_as(0x207A, 2, std::int32_t{100});
    od.set_as(0x207A, 1, std::uint16_t{0x0041}); // single position, both directions
    Epos2Io io(od);
    io.update({.now = 0.001, .position = 5000});
    EXPECT_FALSE(io.output(1));
    io.update({.now = 0.002, .position = 50});
    EXPECT_TRUE(io.output(1)) << "passed 100 downwards";
}

// Without a brake output the power stage follows the device control at once (no delays).
TEST_F(Epos2DriveIo, WithoutBrakeOutputNoDelayInTheSequence) {
    configure_and_enable(1);
    const std::optional<Tpdo> power_on = first_tpdo_with(kVoltageEnabledBit, 0);
    const std::optional<Tpdo> enabled = first_tpdo_in(kOperationEnabled, 0);
    ASSERT_TRUE(power_on && enabled);
    EXPECT_LE(enabled->time - power_on->time, 0.0015);
    controlword(kShutdown);
    run_with_sync(2ms);
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);
}

} // namespace
} // namespace eposp::drives::epos2
