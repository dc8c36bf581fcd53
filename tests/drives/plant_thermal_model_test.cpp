// The first-order thermal model of a winding or power stage against its closed form.
#include "eposp/drives/plant/thermal_model.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::drives::plant {
namespace {

ThermalModel heated(ThermalModel model, double power, double seconds, double dt) {
    for (int i = 0; i < static_cast<int>(std::lround(seconds / dt)); ++i) {
        model.step(power, dt);
    }
    return model;
}

// T(t) = T_a + P·R_th·(1 − e^(−t/τ)): 63.2 % of the rise after one time constant.
TEST(ThermalModel, RisesByOneMinusInverseEAfterOneTimeConstant) {
    const ThermalModel model = heated(
        ThermalModel({.ambient_temperature = 25, .thermal_resistance = 2, .time_constant = 10}), 30,
        10, 1e-3);
    EXPECT_NEAR(model.temperature(), 25 + 60 * (1 - std::exp(-1.0)), 1e-9);
}

TEST(ThermalModel, SettlesAtAmbientPlusPowerTimesThermalResistance) {
    const ThermalModel model = heated(
        ThermalModel({.ambient_temperature = 40, .thermal_resistance = 1.5, .time_constant = 2}),
        20, 60, 0.01);
    EXPECT_NEAR(model.temperature(), 70, 1e-6);
    EXPECT_DOUBLE_EQ(model.steady_state_temperature(20), 70);
}

// The step is exact for a constant power: one second in 1 ms or in 0.1 ms steps ends alike.
TEST(ThermalModel, StepLengthDoesNotChangeTheTemperature) {
    const ThermalParameters body{
        .ambient_temperature = 25, .thermal_resistance = 3, .time_constant = 0.7};
    EXPECT_NEAR(heated(ThermalModel(body), 5, 1, 1e-3).temperature(),
                heated(ThermalModel(body), 5, 1, 1e-4).temperature(), 1e-9);
}

TEST(ThermalModel, CoolsBackToAmbientWithoutPower) {
    ThermalModel model({.ambient_temperature = 25, .thermal_resistance = 1, .time_constant = 1});
    model.set_temperature(125);
    EXPECT_NEAR(heated(model, 0, 1, 1e-3).temperature(), 25 + 100 * std::exp(-1.0), 1e-9);
}

// ESCON2 FW spec 6.2.14.1: the nominal current at 25 °C ambient ends at the maximal winding
// temperature.
TEST(ThermalModel, WindingUnderNominalCurrentReachesItsMaximalTemperature) {
    const ThermalParameters winding = winding_thermal_parameters(1.47, 2.5, 2.8, 125);
    EXPECT_NEAR(winding.thermal_resistance, 100 / (1.47 * 1.47 * 2.5), 1e-12);
    const ThermalModel model = heated(ThermalModel(winding), 1.47 * 1.47 * 2.5, 60, 1e-3);
    EXPECT_NEAR(model.temperature(), 125, 1e-6);
}

TEST(ThermalModel, NewParametersKeepTheTemperature) {
    ThermalModel model = heated(ThermalModel(ThermalParameters{}), 10, 4, 1e-3);
    const double before = model.temperature();
    model.set_parameters({.ambient_temperature = 25, .thermal_resistance = 1, .time_constant = 8});
    EXPECT_EQ(model.temperature(), before);
}

TEST(ThermalModel, MeaninglessParametersAreRefused) {
    EXPECT_THROW(
        ThermalModel({.ambient_temperature = 25, .thermal_resistance = 1, .time_constant = 0}),
        std::invalid_argument);
    EXPECT_THROW(
        ThermalModel({.ambient_temperature = 25, .thermal_resistance = -1, .time_constant = 1}),
        std::invalid_argument);
    EXPECT_THROW(winding_thermal_parameters(0, 1, 1, 125), std::invalid_argument);
}

} // namespace
} // namespace eposp::drives::plant
