#pragma once

namespace eposp::drives::motion {

/// The motor data the I²t limitation uses (EPOS2 FW spec 8.2.130).
struct I2tParameters {
    double continuous_current = 5;    ///< A, 0x6410 sub 1
    double output_current_limit = 10; ///< A, 0x6410 sub 2
    double time_constant = 4;         ///< s, 0x6410 sub 5 (in 100 ms)
};

/// The output current limitation according to the I²t method (EPOS2 FW spec 5.14.1): the
/// winding's heating is the square of the current relative to the Continuous Current Limit
/// 0x6410 sub 1, filtered with the Thermal Time Constant Winding 0x6410 sub 5; once it reaches
/// the continuous level (1), the output current is reduced to the continuous current limit until
/// the current falls below it. A current of k times the continuous limit is allowed for
/// −τ·ln(1 − 1/k²) (figure 5-40: k = 2 for 0.29·τ). Statusword bit 11 shows the reduction.
class I2tCurrentLimit {
public:
    I2tCurrentLimit() = default;
    explicit I2tCurrentLimit(const I2tParameters& parameters) : parameters_(parameters) {}

    /// New motor data; the winding keeps its heat.
    void set_parameters(const I2tParameters& parameters) {
        parameters_ = parameters;
        gain_dt_ = 0;
    }
    /// The measured current during the last `dt` seconds.
    void update(double current, double dt);
    /// The current limit in force, A.
    double limit() const;
    /// The reduction is in force (statusword bit 11 "internal limit active").
    bool limiting() const { return load_ >= 1; }

private:
    I2tParameters parameters_;
    double load_ = 0;    ///< (I / I_continuous)² filtered: 1 is the winding's maximal temperature
    double gain_dt_ = 0; ///< the step the filter gain was computed for (one exp per change)
    double gain_ = 0;
};

} // namespace eposp::drives::motion
