// The units of 3.3 and the polarity of 8.2.41 on the CAN-only bench: Velocity Notation Index
// 0x608B scales every velocity object (rpm × 10^index), and 0x2008 bit 8 turns the motor the
// other way for the same demands.
#include "epos2_bus_fixture.hpp"

#include <cmath>
#include <numbers>

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::AbortCode;
using canopen::encode;

// The reference axis' encoder: 500 pulses, 2000 qc per turn.
constexpr double kCountsPerTurn = 2000;

// 3.3, 8.2.114: with -1 the velocity unit is 0.1 rpm. 0x60FF = 10 000 is 1000 rpm, reached at the
// profile acceleration of 10 000 rpm/s (the acceleration unit keeps its own notation index,
// 0x608D = 0) in 0.1 s; 0x606B, 0x606C and 0x2028 show tenths of rpm. Table 8-119's bound of
// 0x607F is 25 000 rpm = 250 000 units.
TEST_F(Epos2DriveOnBus, VelocityNotationIndexScalesTheVelocityObjects) {
    write(0x608B, 0, encode(std::int8_t{-1}));
    EXPECT_EQ(try_write(0x607F, 0, encode(std::uint32_t{250'001})), AbortCode::ValueTooHigh);
    write(0x607F, 0, encode(std::uint32_t{100'000}));
    configure_and_enable(3);
    write(0x60FF, 0, encode(std::int32_t{10'000}));
    loop.run_for(50ms - 20ms); // the write's SDO exchange took 20 ms of the ramp
    EXPECT_NEAR(drive.objects().get_as<std::int32_t>(0x606B, 0), 5'000, 300);
    loop.run_for(1s);
    EXPECT_EQ(drive.objects().get_as<std::int32_t>(0x606B, 0), 10'000);
    EXPECT_NEAR(drive.axis().velocity_actual() * 60 / kCountsPerTurn, 1000, 15) << "rpm";
    EXPECT_NEAR(read<std::int32_t>(0x2028, 0), 10'000, 100);
    EXPECT_NEAR(drive.objects().get_as<std::int32_t>(0x606C, 0), 10'000, 300);
}

// 8.2.41, table 8-83 bit 8: "1 = Inverse: If demanded velocity or position is positive, direction
// of rotation is CW". The same move to +20 000 qc turns the motor the other way (the plant's
// positive angle is CCW); the firmware's positions and the encoder counter (8.2.44: "multiplied
// by Polarity") read +20 000 as with the normal polarity.
TEST_F(Epos2DriveOnBus, PolarityBitTurnsTheMotorTheOtherWay) {
    write(0x2008, 0, encode(std::uint16_t{0x0100}));
    configure_and_enable(1);
    controlword_and_target(kEnableOperation | kNewSetpoint, 20'000);
    run_with_sync(1500ms);
    EXPECT_NEAR(drive.objects().get_as<std::int32_t>(0x6064, 0), 20'000, 2);
    EXPECT_NEAR(static_cast<double>(drive.axis().position_actual()), -20'000, 2);
    EXPECT_LT(drive.axis().motor().state().angle, -9 * 2 * std::numbers::pi) << "ten turns CW";
    EXPECT_NEAR(static_cast<std::int32_t>(read<std::uint32_t>(0x2020, 0)), 20'000, 2);
}

} // namespace
} // namespace eposp::drives::epos2
