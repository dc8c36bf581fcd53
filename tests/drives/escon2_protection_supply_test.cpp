// The ESCON2's power supply supervision (ESCON2 FW spec 6.2.10, 6.2.11, 7.1.6, 7.1.7): the
// thresholds, their hysteresis and when each error is raised and may be cleared.
#include "eposp/drives/escon2/protection/power_supply_supervision.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

using Codes = std::vector<DeviceErrorCode>;

// 6.2.11.1: enabling needs more than the undervoltage limit (Module 60/30: 7.5 V).
TEST(Escon2PowerSupply, EnablingNeedsMoreThanTheUndervoltageLimit) {
    PowerSupplySupervision supply;
    supply.update(7.5, false);
    EXPECT_FALSE(supply.may_enable());
    EXPECT_TRUE(supply.conditions().empty()); // not enabled: no error
    supply.update(7.51, false);
    EXPECT_TRUE(supply.may_enable());
}

// Below the limit while enabled: 0x3220, present until above 7.5 V + 0.25 V hysteresis.
TEST(Escon2PowerSupply, UndervoltageWhileEnabledClearsAboveLimitPlusHysteresis) {
    PowerSupplySupervision supply;
    supply.update(24, true);
    EXPECT_TRUE(supply.conditions().empty());
    supply.update(7.4, true);
    EXPECT_EQ(supply.conditions(), Codes{DeviceErrorCode::Undervoltage});
    supply.update(7.7, false);
    EXPECT_TRUE(supply.undervoltage());
    supply.update(7.76, false);
    EXPECT_FALSE(supply.undervoltage());
}

// 6.2.11.2: above the overvoltage limit "regardless of the enabled state" 0x3210, present until
// below 65 V − 1 V.
TEST(Escon2PowerSupply, OvervoltageEnabledOrNotClearsBelowLimitMinusHysteresis) {
    PowerSupplySupervision supply;
    supply.update(65, false);
    EXPECT_TRUE(supply.conditions().empty());
    supply.update(65.1, false);
    EXPECT_EQ(supply.conditions(), Codes{DeviceErrorCode::Overvoltage});
    supply.update(64.2, false);
    EXPECT_TRUE(supply.overvoltage());
    supply.update(63.9, false);
    EXPECT_FALSE(supply.overvoltage());
}

// The Nano 24/2's figures (tables 41 - 44): 4.5 V / 50 mV, 31 V / 2 V.
TEST(Escon2PowerSupply, NanoThresholds) {
    PowerSupplySupervision supply({.undervoltage_limit = 4.5,
                                   .undervoltage_hysteresis = 0.05,
                                   .overvoltage_limit = 31,
                                   .overvoltage_hysteresis = 2});
    supply.update(4.4, true);
    supply.update(4.54, true);
    EXPECT_TRUE(supply.undervoltage());
    supply.update(4.56, true);
    EXPECT_FALSE(supply.undervoltage());
    supply.update(31.5, true);
    supply.update(29.5, true);
    EXPECT_TRUE(supply.overvoltage());
    supply.update(28.9, true);
    EXPECT_FALSE(supply.overvoltage());
}

// 6.2.11: "The undervoltage limit must be lower than overvoltage limit minus overvoltage
// hysteresis minus undervoltage hysteresis".
TEST(Escon2PowerSupply, LimitsTooCloseAreRefused) {
    PowerSupplySupervision supply;
    const SupplyLimits close{.undervoltage_limit = 63.75,
                             .undervoltage_hysteresis = 0.25,
                             .overvoltage_limit = 65,
                             .overvoltage_hysteresis = 1};
    EXPECT_TRUE(supply.set_limits(close));
    EXPECT_THROW(PowerSupplySupervision{close}, std::invalid_argument);
    SupplyLimits fine = close;
    fine.undervoltage_limit = 63.7;
    EXPECT_FALSE(supply.set_limits(fine));
    supply.update(63.6, true);
    EXPECT_TRUE(supply.undervoltage()); // the new limit acts
}

// 6.2.10.1: the supply voltage in 0.1 V.
TEST(Escon2PowerSupply, VoltageIsShownInTenthsOfAVolt) {
    PowerSupplySupervision supply;
    supply.update(24.04, false);
    EXPECT_EQ(supply.voltage_object(), 240);
    supply.update(-1, false);
    EXPECT_EQ(supply.voltage_object(), 0);
}

} // namespace
} // namespace eposp::drives::escon2
