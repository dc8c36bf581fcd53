#pragma once

#include "eposp/drives/plant/thermal_model.hpp"

namespace eposp::drives::epos2 {

/// The power stage as a heated body (plant::ThermalModel) for the Overtemperature Error 0x4210
/// (EPOS2 FW spec 4.2.7: "Temperature at device's power stage too high"). The spec gives no
/// figures; these defaults keep an EPOS2 24/5 at its 5 A continuous current and 25 °C ambient
/// well below the limit (about 40 °C), and let a hot cabinet or a long overload reach it.
struct PowerStageThermal {
    plant::ThermalParameters body{
        .ambient_temperature = 25, .thermal_resistance = 5, .time_constant = 60};
    double idle_losses = 0.5;     ///< W, with the power stage on
    double loss_resistance = 0.1; ///< Ω: the bridge's conduction losses I²·R of the motor current
    double max_temperature = 100; ///< °C: above it 0x4210; a fault reset needs it below
};

/// The power stage's temperature, stepped each control period.
class PowerStageTemperature {
public:
    explicit PowerStageTemperature(const PowerStageThermal& thermal)
        : thermal_(thermal), body_(thermal.body) {}

    /// The air around the drive (a hot cabinet), from now on.
    void set_ambient_temperature(double celsius);
    /// `dt` s with the motor current `amperes`, the power stage on or off.
    void update(double amperes, bool power_stage_on, double dt);
    double temperature() const { return body_.temperature(); }
    bool too_high() const { return body_.temperature() > thermal_.max_temperature; }

private:
    PowerStageThermal thermal_;
    plant::ThermalModel body_;
};

} // namespace eposp::drives::epos2
