// Position Mode (-1), Velocity Mode (-2) and Current Mode (-3) of the simulated EPOS2 (EPOS2 FW
// spec 5.6, 5.11, 5.13): set values by SDO and RPDO move the axis through the matching control
// loop, within the limits of their configuration tables; quickstop, halt, mode switches. The
// reference axis has 2000 qc per turn, so 1 rpm is 33.3 qc/s. All on the CAN-only bench.
#include "epos2_bus_fixture.hpp"

#include <cmath>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::AbortCode;
using canopen::encode;

constexpr std::int8_t kPositionMode = -1;
constexpr std::int8_t kVelocityMode = -2;
constexpr std::int8_t kCurrentMode = -3;
constexpr std::int8_t kDiagnosticMode = -4;
constexpr std::int8_t kProfileVelocity = 3;
constexpr std::uint16_t kQuickStopCommand = 0x000B; // table 3-6: 0xxx x01x from Operation Enable
constexpr std::uint16_t kHalt = 0x0100;
constexpr std::uint16_t kQuickStopActive = 0x0007; // table 3-4 under kStateMask
constexpr std::uint16_t kModeBits = 0x3400;        // table 8-114: bits 10, 12, 13
constexpr double kCountsPerRpm = 2000.0 / 60;

class DirectModes : public Epos2DriveOnBus {
public:
    explicit DirectModes(plant::AxisParameters axis = plant::test::tuned_axis())
        : Epos2DriveOnBus(axis) {}

    /// 0x607F = 1000 rpm, 0x60C5 = 10 000 rpm/s (v = 33 333 qc/s, a = 333 333 qc/s²).
    void limit_profile() {
        write(0x607F, 0, encode(std::uint32_t{1000}));
        write(0x60C5, 0, encode(std::uint32_t{10000}));
    }
    std::int32_t position() { return drive.objects().get_as<std::int32_t>(0x6064, 0); }
    std::int32_t velocity_rpm() { return drive.objects().get_as<std::int32_t>(0x606C, 0); }
    std::int16_t current_ma() { return drive.objects().get_as<std::int16_t>(0x6078, 0); }
};

// 5.6: a set value by SDO is approached at 0x607F and 0x60C5 (table 5-37) and reached: the
// demand 0x6062 arrives at the trapezoid time v/a + d/v = 0.7 s, the axis follows.
TEST_F(DirectModes, PositionModeSetValueIsReachedWithinMaxVelocityAndAcceleration) {
    limit_profile();
    configure_and_enable(kPositionMode);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kPositionMode);
    const double commanded = now(); // the SDO write takes effect within a millisecond
    write(0x2062, 0, encode(std::int32_t{20000}));
    double arrived = -1;
    std::int32_t fastest = 0;
    for (int ms = 0; ms < 1000; ++ms) {
        run_with_sync(1ms);
        fastest = std::max(fastest, std::abs(drive.objects().get_as<std::int32_t>(0x606B, 0)));
        if (arrived < 0 && drive.objects().get_as<std::int32_t>(0x6062, 0) == 20000) {
            arrived = now() - commanded;
        }
    }
    EXPECT_NEAR(arrived, 0.1 + 20000 / (1000 * kCountsPerRpm), 0.005);
    EXPECT_LE(fastest, 1000) << "0x606B within 0x607F";
    EXPECT_NEAR(position(), 20000, 5);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
    EXPECT_EQ(tpdos.back().statusword & kModeBits, 0) << "table 8-114 has none for this mode";
}

// 5.6 / 8.2.52: the master generates the profile; a set value streamed by RPDO every
// millisecond is the position demand itself, and the axis follows it closely.
TEST_F(DirectModes, PositionModeFollowsASetValueStreamedByRpdo) {
    const std::uint32_t rpdo2 = 0x300 + kNode;
    write(0x1401, 1, encode(std::uint32_t{0x8000'0000 | rpdo2})); // invalid while mapped
    write(0x1601, 0, encode(std::uint8_t{0}));
    write(0x1601, 1, encode(std::uint32_t{0x2062'0020}));
    write(0x1601, 0, encode(std::uint8_t{1}));
    write(0x1401, 1, encode(rpdo2));
    configure_and_enable(kPositionMode);
    std::int32_t largest_lag = 0;
    for (std::int32_t ms = 1; ms <= 500; ++ms) {
        const std::int32_t set_value = 10 * ms; // 10 000 qc/s = 300 rpm
        const canopen::Bytes bytes = encode(set_value);
        master->send(can::Frame::data_frame(rpdo2, {bytes[0], bytes[1], bytes[2], bytes[3]}));
        run_with_sync(1ms);
        ASSERT_EQ(drive.objects().get_as<std::int32_t>(0x6062, 0), set_value) << ms;
        if (ms > 100) {
            largest_lag = std::max(largest_lag, std::abs(set_value - position()));
        }
    }
    EXPECT_LT(largest_lag, 50) << "the position loop with feed-forward follows";
}

// Table 5-38: Software Position Limit 0x607D limits the Position Mode Setting Value.
TEST_F(DirectModes, PositionModeSetValueIsLimitedToTheSoftwarePositionLimits) {
    limit_profile();
    write(0x607D, 1, encode(std::int32_t{-1000}));
    write(0x607D, 2, encode(std::int32_t{3000}));
    configure_and_enable(kPositionMode);
    write(0x2062, 0, encode(std::int32_t{50000}));
    run_with_sync(500ms);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x6062, 0), 3000);
    EXPECT_NEAR(position(), 3000, 5);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled) << "no 0xFF09";
}

class DirectModesWithBlockedLoad : public DirectModes {
protected:
    static plant::AxisParameters blocked_axis() {
        plant::AxisParameters axis = plant::test::tuned_axis();
        axis.plant.load.coulomb_friction = 100; // far beyond the motor's torque
        return axis;
    }
    DirectModesWithBlockedLoad() : DirectModes(blocked_axis()) {}
};

// 5.9.1.1: the position loop of Position Mode watches the Maximal Following Error 0x6065.
TEST_F(DirectModesWithBlockedLoad, PositionModeFollowingErrorRaises8611) {
    configure_and_enable(kPositionMode);
    write(0x2062, 0, encode(std::int32_t{20000}));
    run_with_sync(500ms);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1) & 0xFFFF, 0x8611U);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kFault);
}

// 5.14.1: the I²t limitation. 1 A on a blocked axis with a continuous current of 500 mA and
// τ = 1 s heats the winding to its limit after −τ·ln(1 − 0.5²) = 0.288 s: from then on the current
// is the continuous current and statusword bit 11 "internal limit active" is set; a set value
// below the continuous current releases it.
TEST_F(DirectModesWithBlockedLoad, CurrentAboveTheContinuousLimitIsReducedAfterTheI2tTime) {
    write(0x6410, 1, encode(std::uint16_t{500}));
    write(0x6410, 5, encode(std::uint16_t{10}));
    configure_and_enable(kCurrentMode);
    EXPECT_EQ(tpdos.back().statusword & 0x0800, 0);
    const double commanded = now(); // the SDO write takes effect within a millisecond
    write(0x2030, 0, encode(std::int16_t{1000}));
    run_with_sync(500ms);
    const std::optional<Tpdo> limited = first_tpdo_with(0x0800, commanded);
    ASSERT_TRUE(limited.has_value());
    EXPECT_NEAR(limited->time - commanded, -std::log(0.75), 0.004);
    EXPECT_NEAR(current_ma(), 500, 15);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
    write(0x2030, 0, encode(std::int16_t{300}));
    run_with_sync(5ms);
    EXPECT_EQ(tpdos.back().statusword & 0x0800, 0);
    EXPECT_NEAR(current_ma(), 300, 15);
}

// 5.11: the velocity loop reaches the set value, ramped at Max Acceleration 0x60C5 (1000 rpm in
// 0.1 s at 10 000 rpm/s); 0x606B shows the demand.
TEST_F(DirectModes, VelocityModeReachesTheSetValueAtMaxAcceleration) {
    limit_profile();
    configure_and_enable(kVelocityMode);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kVelocityMode);
    const double commanded = now(); // the SDO write takes effect within a millisecond
    write(0x206B, 0, encode(std::int32_t{-1000}));
    double ramped = -1;
    while (now() - commanded < 0.4) {
        run_with_sync(1ms);
        if (ramped < 0 && drive.objects().get_as<std::int32_t>(0x606B, 0) == -1000) {
            ramped = now() - commanded;
        }
    }
    EXPECT_NEAR(ramped, 0.1, 0.003);
    EXPECT_NEAR(velocity_rpm(), -1000, 35); // measured in qc per ms: 30 rpm steps
    EXPECT_EQ(tpdos.back().statusword & kModeBits, 0);
}

// 8.2.54 / table 5-55: 0x206B is refused beyond 0x607F, and a 0x607F lowered later bounds the
// demand.
TEST_F(DirectModes, VelocityModeDemandStaysWithinMaximalProfileVelocity) {
    write(0x607F, 0, encode(std::uint32_t{2000}));
    EXPECT_EQ(try_write(0x206B, 0, encode(std::int32_t{2001})), AbortCode::ValueTooHigh);
    configure_and_enable(kVelocityMode);
    write(0x206B, 0, encode(std::int32_t{1500}));
    write(0x607F, 0, encode(std::uint32_t{600}));
    run_with_sync(500ms);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x606B, 0), 600);
    EXPECT_NEAR(velocity_rpm(), 600, 35);
}

// 3.2 transition 11: a quickstop in Velocity Mode ramps down with Quickstop Deceleration 0x6085
// (1000 rpm at 5000 rpm/s: 0.2 s) and holds the axis in Quickstop Active.
TEST_F(DirectModes, VelocityModeQuickStopRampsDownWithQuickstopDeceleration) {
    configure_and_enable(kVelocityMode);
    write(0x6085, 0, encode(std::uint32_t{5000}));
    write(0x206B, 0, encode(std::int32_t{1000}));
    run_with_sync(300ms);
    ASSERT_NEAR(velocity_rpm(), 1000, 35);
    controlword(kQuickStopCommand);
    run_with_sync(100ms);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kQuickStopActive);
    EXPECT_NEAR(velocity_rpm(), 500, 60) << "half way down the ramp";
    run_with_sync(400ms);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kQuickStopActive);
    EXPECT_EQ(velocity_rpm(), 0);
}

// Table 8-113 gives the halt bit to PPM, PVM, HMM and IPM only: in the direct modes bit 8 is
// reserved and the set value keeps commanding.
TEST_F(DirectModes, HaltBitIsReservedInVelocityMode) {
    configure_and_enable(kVelocityMode);
    write(0x206B, 0, encode(std::int32_t{500}));
    controlword(kEnableOperation | kHalt);
    run_with_sync(300ms);
    EXPECT_NEAR(velocity_rpm(), 500, 35);
}

TEST_F(DirectModes, HaltBitIsReservedInPositionMode) {
    limit_profile();
    configure_and_enable(kPositionMode);
    controlword(kEnableOperation | kHalt);
    write(0x2062, 0, encode(std::int32_t{-5000}));
    run_with_sync(600ms);
    EXPECT_NEAR(position(), -5000, 5);
}

TEST_F(DirectModes, HaltBitIsReservedInCurrentMode) {
    configure_and_enable(kCurrentMode);
    controlword(kEnableOperation | kHalt);
    write(0x2030, 0, encode(std::int16_t{200}));
    run_with_sync(10ms);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x2031, 0), 200);
}

// 3.2 transition 11 in Position Mode: the demand leaves the set value and stops on the quickstop
// ramp (1000 rpm at 5000 rpm/s: 0.2 s, 3333 qc); Quickstop Active holds there.
TEST_F(DirectModes, PositionModeQuickStopStopsShortOfTheSetValue) {
    limit_profile();
    configure_and_enable(kPositionMode);
    write(0x6085, 0, encode(std::uint32_t{5000}));
    write(0x2062, 0, encode(std::int32_t{40000}));
    run_with_sync(300ms);
    const std::int32_t at_quickstop = position();
    ASSERT_NEAR(velocity_rpm(), 1000, 35);
    controlword(kQuickStopCommand);
    run_with_sync(500ms);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kQuickStopActive);
    EXPECT_EQ(velocity_rpm(), 0);
    EXPECT_NEAR(position() - at_quickstop, 3333, 100);
}

// 8.2.105: the actual position leaving the software limits raises 0xFF09 in the modes without
// a position set value too; its fault reaction (quickstop) ends in Fault.
TEST_F(DirectModes, VelocityModeBeyondTheSoftwarePositionLimitRaisesFF09) {
    write(0x607D, 2, encode(std::int32_t{5000}));
    configure_and_enable(kVelocityMode);
    write(0x206B, 0, encode(std::int32_t{300}));
    run_with_sync(1500ms);
    EXPECT_EQ(read<std::uint32_t>(0x1003, 1) & 0xFFFF, 0xFF09U);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kFault);
}

// 5.13 / 5.14: the current loop holds the set value; the axis accelerates as torque over inertia
// (k_t · I − Coulomb friction) / J = (0.0234 · 0.3 − 0.001) / 6.05e-6 = 995 rad/s² (9500 rpm/s).
TEST_F(DirectModes, CurrentModeHoldsTheSetCurrentAndAcceleratesAsTorqueOverInertia) {
    configure_and_enable(kCurrentMode);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kCurrentMode);
    write(0x2030, 0, encode(std::int16_t{300}));
    const double commanded = now();
    run_with_sync(20ms);
    const std::int32_t early = velocity_rpm();
    const double early_time = now() - commanded;
    run_with_sync(50ms);
    EXPECT_NEAR(current_ma(), 300, 15);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x2031, 0), 300) << "Current Demand Value";
    const double acceleration = (velocity_rpm() - early) / (now() - commanded - early_time);
    EXPECT_NEAR(acceleration, (0.0234 * 0.3 - 0.001) / 6.05e-6 * 60 / (2 * M_PI), 1500);
    EXPECT_EQ(tpdos.back().statusword & kModeBits, 0);
}

// 8.2.130 sub 4: Maximal Motor Speed caps the speed in Current Mode; the current then drops to
// what the friction takes.
TEST_F(DirectModes, CurrentModeSpeedIsCappedAtMaximalMotorSpeed) {
    write(0x6410, 4, encode(std::uint32_t{1000}));
    configure_and_enable(kCurrentMode);
    write(0x2030, 0, encode(std::int16_t{-300}));
    run_with_sync(1000ms);
    EXPECT_NEAR(velocity_rpm(), -1000, 60);
    EXPECT_GT(current_ma(), -150) << "no longer the set value";
}

// 8.2.50: 0x2030 is refused beyond ± Output Current Limit 0x6410 sub 2, and a limit lowered
// later bounds the demand.
TEST_F(DirectModes, CurrentModeSetValueIsLimitedToTheOutputCurrentLimit) {
    write(0x6410, 2, encode(std::uint16_t{2000}));
    EXPECT_EQ(try_write(0x2030, 0, encode(std::int16_t{-2001})), AbortCode::ValueTooLow);
    write(0x2030, 0, encode(std::int16_t{-1500}));
    write(0x6410, 2, encode(std::uint16_t{400}));
    configure_and_enable(kCurrentMode);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x2031, 0), -400);
}

// 3.2 transition 11 in Current Mode: the quickstop ramp starts from the actual motion.
TEST_F(DirectModes, CurrentModeQuickStopRampsDownFromTheActualVelocity) {
    write(0x6410, 4, encode(std::uint32_t{1000}));
    configure_and_enable(kCurrentMode);
    write(0x6085, 0, encode(std::uint32_t{5000}));
    write(0x2030, 0, encode(std::int16_t{300}));
    run_with_sync(500ms);
    ASSERT_NEAR(velocity_rpm(), 1000, 60);
    controlword(kQuickStopCommand);
    run_with_sync(100ms);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kQuickStopActive);
    EXPECT_NEAR(velocity_rpm(), 500, 90);
    run_with_sync(400ms);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kQuickStopActive);
    EXPECT_EQ(velocity_rpm(), 0);
}

// 8.2.90: the mode changes while enabled; each starts from where the axis is.
TEST_F(DirectModes, ModeSwitchWhileEnabledHandsTheAxisOver) {
    limit_profile();
    configure_and_enable(kVelocityMode);
    write(0x206B, 0, encode(std::int32_t{600}));
    run_with_sync(300ms);
    write(0x2062, 0, encode(std::int32_t{position() + 4000}));
    const std::int32_t target = drive.objects().get_as<std::int32_t>(0x2062, 0);
    write(0x6060, 0, encode(kPositionMode));
    run_with_sync(500ms);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kPositionMode);
    EXPECT_NEAR(position(), target, 5);
    write(0x6060, 0, encode(kCurrentMode));
    write(0x2030, 0, encode(std::int16_t{0}));
    run_with_sync(50ms);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kCurrentMode);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x2031, 0), 0);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
}

// 8.2.90, table 8-118, 0x6502 bit 19: the Diagnostic Mode (-4) is accepted and displayed. maxon
// documents no set value for it (5.2: "Only used for the Diagnostic Wizard"): enabled, the power
// stage holds zero current and the axis stays where it is, with no mode bits (table 8-114).
TEST_F(DirectModes, DiagnosticModeIsAcceptedAndAppliesNoSetValue) {
    configure_and_enable(kDiagnosticMode);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kDiagnosticMode);
    run_with_sync(200ms);
    EXPECT_EQ(position(), 0);
    EXPECT_EQ(current_ma(), 0);
    EXPECT_EQ(drive.axis().current_demand(), 0);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
    EXPECT_EQ(tpdos.back().statusword & kModeBits, 0);
    EXPECT_TRUE(emcys.empty());
}

// A spinning axis switched to the Diagnostic Mode coasts: no torque, friction alone slows it. The
// reference load's Coulomb c = 1 mN·m and viscous b = 1 µN·m·s/rad on J = 6.05 g·cm² give
// ω(t) = (ω0 + c/b)·e^(−b·t/J) − c/b until it stands still, which it then keeps.
TEST_F(DirectModes, DiagnosticModeLetsTheMotorCoast) {
    configure_and_enable(kProfileVelocity);
    write(0x60FF, 0, encode(std::int32_t{500}));
    run_with_sync(500ms);
    write(0x6060, 0, encode(kDiagnosticMode));
    const double omega0 = drive.axis().motor().state().speed;
    const double switched = now();
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kDiagnosticMode);
    run_with_sync(100ms);
    const double c = 1e-3;
    const double b = 1e-6;
    const double j = 1.05e-6 + 5e-6;
    const double t = now() - switched;
    const double expected = (omega0 + c / b) * std::exp(-b * t / j) - c / b;
    EXPECT_NEAR(drive.axis().motor().state().speed, expected, 0.02 * omega0);
    EXPECT_NEAR(current_ma(), 0, 5);
    run_with_sync(400ms); // beyond J/b·ln(1 + ω0·b/c) ≈ 0.31 s
    EXPECT_EQ(drive.axis().motor().state().speed, 0);
    const std::int32_t rest = position();
    run_with_sync(100ms);
    EXPECT_EQ(position(), rest);
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
}

} // namespace
} // namespace eposp::drives::epos2
