#pragma once

#include "eposp/drives/plant/thermal_model.hpp"

namespace eposp::drives::motion {

/// The motor data the I²t limitation uses (EPOS2 FW spec 8.2.130, ESCON2 FW spec 6.2.14).
struct I2tParameters {
    double continuous_current = 5;    ///< A, EPOS2 0x6410 sub 1, ESCON2 0x3001 sub 1 (nominal)
    double output_current_limit = 10; ///< A, EPOS2 0x6410 sub 2, ESCON2 0x3001 sub 2
    double time_constant = 4;         ///< s, EPOS2 0x6410 sub 5, ESCON2 0x3001 sub 4 (in 0.1 s)
    /// The level below which a limitation is lifted: the EPOS2 lifts it as soon as the winding
    /// is below its limit (1), the ESCON2 once "the I2T level of the motor falls below 90 %"
    /// (ESCON2 FW spec 3.6.2).
    double release_level = 1;
};

/// The output current limitation according to the I²t method (EPOS2 FW spec 5.14.1, ESCON2 FW
/// spec 3.6.2): the winding's heating is the square of the current relative to the continuous
/// (nominal) current, filtered with the thermal time constant of the winding — the thermal model
/// with the temperature rise normalised to the one the continuous current ends at, the I²t level
/// (ESCON2 0x3200 sub 1, 1 = 100 %). Once the level reaches 1, the output current is reduced to
/// the continuous current until the level falls below the release level. Statusword bit 11 shows
/// the reduction.
class I2tCurrentLimit {
public:
    I2tCurrentLimit() : I2tCurrentLimit(I2tParameters{}) {}
    explicit I2tCurrentLimit(const I2tParameters& parameters);

    /// New motor data; the winding keeps its heat.
    void set_parameters(const I2tParameters& parameters);
    /// The measured current during the last `dt` seconds. Inline: a drive calls it every 0.1 ms.
    void update(double current, double dt) {
        if (parameters_.continuous_current <= 0) {
            hold_without_continuous_current(current);
            return;
        }
        const double ratio = current / parameters_.continuous_current;
        // The normalised winding's steady state is its power: 0 + p · 1 is p, bit for bit (a
        // square is never −0).
        winding_.step_towards(ratio * ratio, dt);
        if (level() >= 1) {
            limiting_ = true;
        } else if (level() < parameters_.release_level) {
            limiting_ = false;
        }
    }
    /// The current limit in force, A.
    double limit() const;
    /// The reduction is in force (statusword bit 11 "internal limit active").
    bool limiting() const { return limiting_; }
    /// The I²t level: 1 (100 %) is the winding at its maximal temperature; above 1 is possible.
    double level() const { return winding_.temperature(); }

private:
    void hold_without_continuous_current(double current);

    I2tParameters parameters_;
    plant::ThermalModel winding_; ///< ambient 0, R_th 1, power (I / I_continuous)²
    bool limiting_ = false;
};

/// ESCON2 FW spec 3.6.2, figure 9 (EPOS2 figure 5-40): the time a current of `normalised_peak`
/// times the continuous current lasts from a cold winding (I²t level 0 %) until the limitation
/// sets in, T_peak = −τ·ln(1 − 1/k²); unlimited (infinity) for k ≤ 1.
double peak_current_duration(double normalised_peak, double time_constant);

/// ESCON2 FW spec 3.6.2: the thermal time constant winding from the peak current I_peak that a
/// data sheet permits for T_peak, τ = −T_peak / ln(1 − (I_N / I_peak)²). I_peak must exceed I_N.
double thermal_time_constant(double peak_current, double peak_duration, double nominal_current);

/// ESCON2 FW spec 3.6.2, figure 10: the largest ON current (normalised by the nominal current)
/// a cyclic ON/OFF current of `duty_cycle` (T_on / T_total, 0 … 1) and period `total_time`
/// keeps up for ever without the limitation: the level at the end of each ON time settles at
/// k²·(1 − e^(−T_on/τ)) / (1 − e^(−T_total/τ)), which must stay below 1.
double max_cyclic_on_current(double duty_cycle, double total_time, double time_constant);

} // namespace eposp::drives::motion
