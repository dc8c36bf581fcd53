// The ESCON2's temperature supervision (ESCON2 FW spec 6.2.12, 6.2.56, 7.1.8 - 7.1.10), alone
// and with a power stage heated through the thermal model.
#include "eposp/drives/escon2/protection/output_current_limitation.hpp"
#include "eposp/drives/escon2/protection/thermal_supervision.hpp"
#include "eposp/drives/plant/thermal_model.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace eposp::drives::escon2 {
namespace {

using Codes = std::vector<DeviceErrorCode>;

// Table 95 on a Module 60/30 (max 110 °C): the warning above 100 °C, the error at 110 °C.
TEST(Escon2ThermalSupervision, PowerStageWarnsAboveMaxMinusTenAndFailsAtMax) {
    ThermalSupervision supervision;
    supervision.update(100, 40);
    EXPECT_TRUE(supervision.conditions().empty());
    supervision.update(100.5, 40);
    EXPECT_EQ(supervision.conditions(), Codes{DeviceErrorCode::ThermalPowerStageOverloadWarning});
    supervision.update(110, 40);
    EXPECT_EQ(supervision.conditions(), Codes{DeviceErrorCode::ThermalPowerStageOverload});
    supervision.update(109.9, 40); // 7.1.8: clearable below the critical threshold
    EXPECT_FALSE(supervision.power_stage_error());
    EXPECT_TRUE(supervision.power_stage_warning());
    supervision.update(99, 40); // 7.1.9: the warning clears itself below the threshold
    EXPECT_TRUE(supervision.conditions().empty());
}

// Tables 45 / 46: the logic section fails above 108 °C and stays until below 98 °C.
TEST(Escon2ThermalSupervision, LogicSectionFailsAboveItsLimitWithHysteresis) {
    ThermalSupervision supervision;
    supervision.update(25, 108);
    EXPECT_FALSE(supervision.logic_section_error());
    supervision.update(25, 108.1);
    EXPECT_EQ(supervision.conditions(), Codes{DeviceErrorCode::ThermalLogicSectionOverload});
    supervision.update(25, 98.5);
    EXPECT_TRUE(supervision.logic_section_error());
    supervision.update(25, 97.9);
    EXPECT_FALSE(supervision.logic_section_error());
    ThermalSupervision micro({.max_power_stage_temperature = 100,
                              .logic_section_limit = 115,
                              .logic_section_hysteresis = 10}); // ESCON2 Micro 60/5
    micro.update(90.5, 112);
    EXPECT_EQ(micro.conditions(), Codes{DeviceErrorCode::ThermalPowerStageOverloadWarning});
}

// A power stage heated by 40 W through 2.5 K/W from 25 °C ends at 125 °C: it passes the warning
// temperature, where the current limit starts to fall, and reaches the error at 110 °C after
// τ·ln(100 / 15).
TEST(Escon2ThermalSupervision, HeatedPowerStageWarnsDeratesAndFails) {
    plant::ThermalModel power_stage(
        {.ambient_temperature = 25, .thermal_resistance = 2.5, .time_constant = 30});
    ThermalSupervision supervision;
    CurrentLimitationParameters parameters;
    parameters.power_stage.reset();
    OutputCurrentLimitation limitation(parameters);
    constexpr double kStep = 1e-3;
    double t = 0;
    bool derated_while_warning = false;
    while (!supervision.power_stage_error() && t < 300) {
        power_stage.step(40, kStep);
        t += kStep;
        supervision.update(power_stage.temperature(), 40);
        limitation.update(0, power_stage.temperature(), kStep);
        derated_while_warning |=
            supervision.power_stage_warning() && limitation.limit() < 60 && limitation.limiting();
    }
    EXPECT_TRUE(derated_while_warning);
    EXPECT_NEAR(t, 30 * std::log(100.0 / 15.0), 2 * kStep);
    EXPECT_EQ(limitation.limit(), 0);
}

} // namespace
} // namespace eposp::drives::escon2
