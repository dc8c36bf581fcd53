#pragma once

namespace eposp::drives::plant {

/// A body that heats by dissipated power and cools to its ambient through one thermal resistance
/// (motor winding, power stage, logic section): the first-order model behind the I2t method
/// (ESCON2 FW spec 3.6.2, EPOS2 FW spec 5.14.1) and the temperatures of ESCON2 FW spec 6.2.12 /
/// 6.2.56.
struct ThermalParameters {
    double ambient_temperature = 25; ///< °C
    double thermal_resistance = 1;   ///< K/W from the body to its ambient
    double time_constant = 4;        ///< s; ESCON2 0x3001 sub 4 (in 0.1 s) for the winding
};

/// The parameters that make a motor winding reach `max_temperature` under its nominal current
/// (ESCON2 FW spec 6.2.14.1: "continuous operation ... at this current level and at 25 °C
/// ambient will ultimately cause the winding to reach the specified maximum winding
/// temperature"): R_th = (T_max − T_ambient) / (I_N² · R).
ThermalParameters winding_thermal_parameters(double nominal_current, double resistance,
                                             double time_constant, double max_temperature,
                                             double ambient_temperature = 25);

/// dT/dt = (T_ambient + P·R_th − T) / τ, stepped in virtual time. Exact for a power constant over
/// the step, so the step length does not change the result.
class ThermalModel {
public:
    ThermalModel() = default;
    explicit ThermalModel(const ThermalParameters& parameters);

    /// New parameters; the body keeps its temperature.
    void set_parameters(const ThermalParameters& parameters);
    const ThermalParameters& parameters() const { return parameters_; }

    /// `power` W dissipated during the last `dt` s. Inline: an I²t limitation steps its winding
    /// every 0.1 ms.
    void step(double power, double dt) { step_towards(steady_state_temperature(power), dt); }
    /// `dt` s on the way to `steady_state` °C: step() for a power whose steady-state temperature
    /// the caller knows (a normalised body: ambient 0 and R_th 1 make it the power itself).
    void step_towards(double steady_state, double dt) {
        if (dt != gain_dt_) {
            set_step(dt);
        }
        temperature_ += (steady_state - temperature_) * gain_;
    }
    double temperature() const { return temperature_; }
    /// The temperature `power` W would hold the body at in the end.
    double steady_state_temperature(double power) const {
        return parameters_.ambient_temperature + power * parameters_.thermal_resistance;
    }
    /// Sets the temperature (a body cooled or heated from outside, a test's starting point).
    void set_temperature(double temperature) { temperature_ = temperature; }

private:
    void set_step(double dt);

    ThermalParameters parameters_;
    double temperature_ = parameters_.ambient_temperature;
    double gain_dt_ = 0; ///< the step the gain was computed for: one exp per step length
    double gain_ = 0;
};

} // namespace eposp::drives::plant
