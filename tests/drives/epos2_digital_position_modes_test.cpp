// Master Encoder Mode (-5) and Step/Direction Mode (-6) of the simulated EPOS2 (EPOS2 FW spec
// 5.7, 5.8, 8.2.80): the counter of the digital position input, scaled by 0x2300 sub 2 / 3,
// negated by polarity, displaced by the offset, is the position demand: an electronic gear.
#include "epos2_bus_fixture.hpp"

namespace eposp::drives::epos2 {
namespace {

using namespace test;
using namespace std::chrono_literals;
using canopen::encode;

constexpr std::int8_t kMasterEncoderMode = -5;
constexpr std::int8_t kStepDirectionMode = -6;

class DigitalPositionModes : public Epos2DriveOnBus {
public:
    std::int32_t demand() { return drive.objects().get_as<std::int32_t>(0x6062, 0); }
    std::int32_t desired() { return drive.objects().get_as<std::int32_t>(0x2300, 1); }
};

TEST_F(DigitalPositionModes, TheMasterEncoderCountsTimesTheGearPlusTheOffsetAreTheDemand) {
    write(0x2300, 2, encode(std::uint16_t{3})); // numerator
    write(0x2300, 3, encode(std::uint16_t{2})); // denominator
    write(0x2300, 5, encode(std::int32_t{100}));
    configure_and_enable(kMasterEncoderMode);
    EXPECT_EQ(read<std::int8_t>(0x6061, 0), kMasterEncoderMode);
    // A master turning at 300 rpm (10 000 qc/s): 10 counts per millisecond for 200 ms.
    for (int ms = 0; ms < 200; ++ms) {
        drive.count_digital_position_input(10);
        run_with_sync(1ms);
    }
    EXPECT_EQ(desired(), 2000);
    EXPECT_EQ(demand(), 2000 * 3 / 2 + 100);
    run_with_sync(100ms);
    EXPECT_NEAR(drive.objects().get_as<std::int32_t>(0x6064, 0), 3100, 10) << "the axis follows";
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
    EXPECT_TRUE(emcys.empty());
}

TEST_F(DigitalPositionModes, PolarityOneCountsTheStepsTheOtherWay) {
    write(0x2300, 4, encode(std::uint8_t{1}));
    configure_and_enable(kStepDirectionMode);
    for (int ms = 0; ms < 100; ++ms) {
        drive.count_digital_position_input(5); // step pulses with direction "up"
        run_with_sync(1ms);
    }
    EXPECT_EQ(desired(), -500);
    EXPECT_EQ(demand(), -500);
}

TEST_F(DigitalPositionModes, TheDemandStaysWithinTheSoftwareLimitsAndMaxProfileVelocity) {
    write(0x607D, 2, encode(std::int32_t{1500}));
    write(0x607F, 0, encode(std::uint32_t{1000}));  // 33 333 qc/s
    write(0x60C5, 0, encode(std::uint32_t{10000})); // 333 333 qc/s²
    configure_and_enable(kMasterEncoderMode);
    drive.count_digital_position_input(5000); // a jump of the master
    run_with_sync(10ms);
    // Ten periods accelerating at 0x60C5: a·dt²·(1 + … + 10) = 18 qc, not the jump.
    EXPECT_NEAR(demand(), 18, 1);
    run_with_sync(300ms);
    EXPECT_EQ(demand(), 1500) << "0x607D sub 2";
    EXPECT_EQ(tpdos.back().statusword & kStateMask, kOperationEnabled);
}

TEST_F(DigitalPositionModes, ADenominatorOfZeroHoldsTheDemand) {
    configure_and_enable(kMasterEncoderMode);
    drive.count_digital_position_input(40);
    run_with_sync(20ms);
    EXPECT_EQ(demand(), 40);
    write(0x2300, 3, encode(std::uint16_t{0}));
    drive.count_digital_position_input(40);
    run_with_sync(20ms);
    EXPECT_EQ(desired(), 80);
    EXPECT_EQ(demand(), 40);
}

} // namespace
} // namespace eposp::drives::epos2
