// The supply and temperature supervision wired into the running ESCON2 (6.2.10 - 6.2.12,
// 6.2.56, 7.1.6 - 7.1.10): their errors and warnings with the reactions of table 110, and the
// fault reset refused while the cause is present.
#include "escon2_drive_fixture.hpp"

#include <chrono>
#include <gtest/gtest.h>

namespace eposp::drives::escon2 {
namespace {

using canopen::AbortCode;
using namespace std::chrono_literals;

using namespace test;

class Escon2DriveSupervision : public test::Escon2DriveFixture {
protected:
    void start(double ambient = 25) {
        Escon2DriveConfig config;
        config.power_stage_thermal.ambient_temperature = ambient;
        Escon2DriveFixture::start(config);
        drive->set_ambient_temperature(ambient);
    }
    std::uint16_t error_code() const { return read<std::uint16_t>(0x603F); }
};

// 7.1.7: below the undervoltage limit while enabled; the reset only above limit + hysteresis
// (7.5 V + 0.25 V on the Module).
TEST_F(Escon2DriveSupervision, UndervoltageWhileEnabledAndItsReset) {
    start();
    enable();
    loop.run_for(2ms);
    drive->set_supply_voltage(7.0);
    loop.run_for(2ms);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    EXPECT_EQ(error_code(), 0x3220);
    EXPECT_EQ(drive->objects().get_as<std::uint8_t>(0x1001, 0), 0b0000'0101);
    EXPECT_EQ(drive->objects().get_as<std::uint16_t>(0x2200, 1), 70u);
    drive->set_supply_voltage(7.7);
    loop.run_for(2ms);
    controlword(0x80);
    EXPECT_EQ(statusword() & kStateMask, kFault) << "within the hysteresis";
    controlword(0x00);
    drive->set_supply_voltage(7.8);
    loop.run_for(2ms);
    controlword(0x80);
    EXPECT_EQ(statusword() & kStateMask, kSwitchOnDisabled);
    EXPECT_EQ(error_code(), 0);
}

// 7.1.6: above the overvoltage limit, enabled or not; 0x2201 sub 2 moves the limit.
TEST_F(Escon2DriveSupervision, OvervoltageEvenWhenDisabled) {
    start();
    ASSERT_EQ(drive->objects().write(0x2201, 2, canopen::encode(std::uint32_t{30'000})),
              AbortCode::None);
    drive->set_supply_voltage(31);
    loop.run_for(2ms);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    EXPECT_EQ(error_code(), 0x3210);
}

// 7.1.9, table 95: between max − 10 °C and max the warning, and the current limit derated
// linearly (half of it at 105 °C of 110 °C).
TEST_F(Escon2DriveSupervision, HotPowerStageWarnsAndDerates) {
    start(105);
    drive->objects().set_as(0x6060, 0, std::int8_t{-120});
    enable();
    drive->set_current_set_value(3000);
    loop.run_for(5ms);
    EXPECT_EQ(statusword() & kStateMask, kOperationEnabled);
    EXPECT_NE(statusword() & kWarning, 0);
    EXPECT_EQ(error_code(), 0x4383);
    EXPECT_NEAR(drive->objects().get_as<std::int16_t>(0x3201, 2), 1050, 2);
    EXPECT_NEAR(drive->objects().get_as<std::int32_t>(0x30D1, 2), 1500, 60) << "3 A × 0.5";
    EXPECT_NE(statusword() & (1U << 11), 0);
}

// 7.1.8, 7.1.10: at the maximum power stage temperature, and above the logic section's limit
// (108 °C on the Module), the device is disabled.
TEST_F(Escon2DriveSupervision, OverheatedPowerStageOrLogicSectionDisables) {
    start(109);
    enable();
    loop.run_for(2ms);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    EXPECT_EQ(error_code(), 0x4384) << "logic section above 108 °C";
    controlword(0x80);
    EXPECT_EQ(statusword() & kStateMask, kFault) << "still hot";
    drive->objects().set_as(0x3201, 3, std::uint16_t{1'000});
    loop.run_for(2ms);
    EXPECT_TRUE(drive->objects().find(0x1003, 0) != nullptr);
    bool power_stage_error = false;
    for (std::uint8_t sub = 1; sub <= drive->objects().get_as<std::uint8_t>(0x1003, 0); ++sub) {
        power_stage_error =
            power_stage_error || drive->objects().get_as<std::uint32_t>(0x1003, sub) == 0x4382;
    }
    EXPECT_TRUE(power_stage_error) << "109 °C is above a maximum of 100 °C";
}


// 7.1.36: from a critical load on (0.9, the simulation's threshold) the warning, which leaves the
// state alone; the Clear warning command resets it, and it comes back while the load stays.
TEST_F(Escon2DriveSupervision, CriticalSystemLoadWarns) {
    start();
    enable();
    drive->set_system_load(0.85);
    loop.run_for(2ms);
    EXPECT_EQ(statusword() & kWarning, 0) << "below the critical load";
    drive->set_system_load(0.95);
    loop.run_for(2ms);
    EXPECT_EQ(statusword() & kStateMask, kOperationEnabled);
    EXPECT_NE(statusword() & kWarning, 0);
    EXPECT_EQ(error_code(), 0xFF01);
    EXPECT_EQ(drive->objects().get_as<std::uint32_t>(0x1003, 1), 0x8000'FF01u);
    drive->set_system_load(0.5);
    loop.run_for(2ms);
    EXPECT_NE(statusword() & kWarning, 0) << "reset with the controlword only";
    controlword(0x8F);
    controlword(0x0F);
    EXPECT_EQ(statusword() & kWarning, 0);
    drive->set_system_load(0.95);
    loop.run_for(2ms);
    controlword(0x8F);
    controlword(0x0F);
    loop.run_for(2ms);
    EXPECT_NE(statusword() & kWarning, 0) << "the load is still critical";
}

// 7.1.39: above a load of 1 the regulation misses its periods: disabled at once, and a fault
// reset is refused while the load stays there.
TEST_F(Escon2DriveSupervision, PeakOverloadDisablesUntilTheLoadFalls) {
    start();
    enable();
    drive->set_system_load(1.2);
    loop.run_for(2ms);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    EXPECT_EQ(error_code(), 0xFF06);
    EXPECT_EQ(drive->objects().get_as<std::uint8_t>(0x1001, 0), 0b0000'0001);
    controlword(0x80);
    EXPECT_EQ(statusword() & kStateMask, kFault) << "still overloaded";
    controlword(0x00);
    drive->set_system_load(0.5);
    loop.run_for(2ms);
    controlword(0x80);
    EXPECT_EQ(statusword() & kStateMask, kSwitchOnDisabled);
    EXPECT_EQ(error_code(), 0);
}

// 7.1.37: overloaded for 100 ms (the simulation's watchdog time) the watchdog resets the device:
// it starts again as at power-up, so a value written but not stored is lost, and shows 0xFF02.
TEST_F(Escon2DriveSupervision, LastingOverloadResetsTheDeviceByItsWatchdog) {
    start();
    ASSERT_EQ(drive->objects().write(0x60C5, 0, canopen::encode(std::uint32_t{1234})),
              AbortCode::None);
    enable();
    drive->set_system_load(1.5);
    loop.run_for(98ms);
    EXPECT_EQ(error_code(), 0xFF06);
    EXPECT_EQ(drive->objects().get_as<std::uint32_t>(0x60C5, 0), 1234u) << "not reset yet";
    loop.run_for(3ms);
    EXPECT_EQ(statusword() & kStateMask, kFault);
    EXPECT_NE(drive->objects().get_as<std::uint32_t>(0x60C5, 0), 1234u) << "a power-up";
    // The history starts again at the power-up: the watchdog error first, then what the load
    // that is still there causes in the next control period.
    EXPECT_EQ(drive->objects().get_as<std::uint8_t>(0x1003, 0), 3u);
    EXPECT_EQ(drive->objects().get_as<std::uint32_t>(0x1003, 3), 0xFF02u);
    EXPECT_EQ(drive->objects().get_as<std::uint32_t>(0x1003, 2), 0x8000'FF01u);
    EXPECT_EQ(drive->objects().get_as<std::uint32_t>(0x1003, 1), 0xFF06u);
    drive->set_system_load(0.2);
    loop.run_for(2ms);
    controlword(0x80);
    EXPECT_EQ(statusword() & kStateMask, kSwitchOnDisabled);
}

} // namespace
} // namespace eposp::drives::escon2
