// The errors the simulated machine can cause besides motion errors (EPOS2 FW spec 4.2, table
// 4-11): each with its EMCY frame, error register 0x1001, error history 0x1003, fault reaction
// and recovery.
#include "epos2_bus_fixture.hpp"

#include <array>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::encode;

using EmcyBytes = std::array<std::uint8_t, 8>;

EmcyBytes bytes_of(const std::vector<std::uint8_t>& frame) {
    EmcyBytes bytes{};
    EXPECT_EQ(frame.size(), bytes.size());
    std::copy_n(frame.begin(), std::min(frame.size(), bytes.size()), bytes.begin());
    return bytes;
}

// The error as table 4-11 and 4.1 give it: EMCY (code, register, five zero bytes), the register
// in 0x1001, the newest history entry, and the drive in Fault.
void expect_error(Epos2DriveOnBus& bench, std::uint16_t code, std::uint8_t error_register) {
    ASSERT_FALSE(bench.emcys.empty());
    EXPECT_EQ(bytes_of(bench.emcys.front()),
              (EmcyBytes{static_cast<std::uint8_t>(code), static_cast<std::uint8_t>(code >> 8),
                         error_register, 0, 0, 0, 0, 0}));
    EXPECT_EQ(bench.read<std::uint8_t>(0x1001, 0), error_register);
    EXPECT_EQ(bench.read<std::uint8_t>(0x1003, 0), 1U) << "one entry in the history";
    EXPECT_EQ(bench.read<std::uint32_t>(0x1003, 1) & 0xFFFF, code);
    EXPECT_EQ(bench.drive.state(), motion::DriveState::Fault);
    EXPECT_EQ(bench.read<std::uint16_t>(0x6041, 0) & kStateMask, kFault);
}

class Epos2DriveErrors : public Epos2DriveOnBus {
public:
    using Epos2DriveOnBus::Epos2DriveOnBus;
};

// 4.2.5: "Power supply voltage too high"; "d": disabled at once; a fault reset is refused until
// the supply is back in range.
TEST_F(Epos2DriveErrors, OvervoltageRaises3210AndDisables) {
    configure_and_enable(1);
    drive.set_supply_voltage(30);
    run_with_sync(5ms);
    expect_error(*this, 0x3210, 0x04);
    EXPECT_EQ(drive.axis().mode(), plant::ControlMode::PowerOff);

    controlword(kFaultReset);
    run_with_sync(5ms);
    controlword(0);
    run_with_sync(5ms);
    EXPECT_EQ(drive.state(), motion::DriveState::Fault) << "supply still too high";

    drive.set_supply_voltage(24);
    controlword(kFaultReset);
    run_with_sync(5ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
    EXPECT_EQ(read<std::uint8_t>(0x1001, 0), 0);
    EXPECT_EQ(bytes_of(emcys.back()), (EmcyBytes{}));
}

// 4.2.6: "Supply voltage is too low for operation", also while the power stage is off.
TEST_F(Epos2DriveErrors, UndervoltageRaises3220EvenWhenDisabled) {
    drive.set_supply_voltage(8);
    nmt(canopen::NmtCommand::Start);
    run_with_sync(5ms);
    expect_error(*this, 0x3220, 0x04);

    drive.set_supply_voltage(12);
    controlword(kFaultReset);
    run_with_sync(5ms);
    EXPECT_EQ(drive.state(), motion::DriveState::SwitchOnDisabled);
}

class Epos2DriveOvercurrent : public Epos2DriveErrors {
protected:
    // A load the motor cannot turn, and a power stage that trips at 5 A.
    static plant::AxisParameters stalled_axis() {
        plant::AxisParameters axis = plant::test::tuned_axis();
        axis.plant.load.coulomb_friction = 100;
        axis.plant.power_stage.overcurrent = 5;
        return axis;
    }

public:
    Epos2DriveOvercurrent() : Epos2DriveErrors(stalled_axis()) {}
};

// 4.2.3: "Controller gains too high": the output current limit 0x6410 sub 2, raised by SDO while
// the axis runs, lets the position controller of a stalled motor drive its current past the
// power stage's limit. The following error is off so that it does not stop the drive first.
TEST_F(Epos2DriveOvercurrent, OutputCurrentLimitWrittenLaterLetsTheCurrentTrip2310) {
    write(0x6065, 0, encode(std::uint32_t{0xFFFF'FFFF}));
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 20000);
    run_with_sync(300ms);
    EXPECT_TRUE(emcys.empty()) << "3 A, the default limit, stays below the 5 A trip";
    EXPECT_NEAR(drive.axis().current_actual(), 3.0, 0.1);

    write(0x6410, 2, encode(std::uint16_t{8000}));
    run_with_sync(50ms);
    expect_error(*this, 0x2310, 0x02);
    EXPECT_EQ(drive.axis().current_actual(), 0.0) << "power stage off";
}

// 4.2.18: the CAN controller goes bus-off: an "a" error (0x6007 = 3 by default: quickstop, then
// Fault). The controller cannot send while bus-off; the EMCY leaves once it has recovered.
TEST_F(Epos2DriveErrors, BusOffRaises81FDWithTheAbortConnectionReaction) {
    configure_and_enable(1);
    device->force_error_state(can::ErrorState::BusOff);
    EXPECT_EQ(device->error_state(), can::ErrorState::BusOff);
    run_with_sync(100ms); // automatic recovery after 128 × 11 recessive bits
    EXPECT_EQ(device->error_state(), can::ErrorState::Active);
    expect_error(*this, 0x81FD, 0x10);
}

} // namespace
} // namespace eposp::drives::epos2
