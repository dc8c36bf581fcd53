#pragma once

#include "eposp/drives/motion/i2t_current_limit.hpp"

#include <optional>

namespace eposp::drives::escon2 {

/// What the output current limitation works from: the motor data 0x3001 (nominal current sub 1,
/// output current limit sub 2, thermal time constant winding sub 4), the power stage's own I²t
/// (absent on the ESCON2 Nano 24/2, 6.2.56) and Max temperature power stage 0x3201 sub 3.
struct CurrentLimitationParameters {
    motion::I2tParameters motor{.continuous_current = 30,
                                .output_current_limit = 60,
                                .time_constant = 4,
                                .release_level = kReleaseLevel};
    /// The power stage's rating as a winding would have it; the manual gives no figures, so
    /// the defaults take its nominal and peak current (tables 53, 54) with a time constant of
    /// the order of a power stage's heat sink.
    std::optional<motion::I2tParameters> power_stage =
        motion::I2tParameters{.continuous_current = 30,
                              .output_current_limit = 60,
                              .time_constant = 4,
                              .release_level = kReleaseLevel};
    double max_power_stage_temperature = 110; ///< °C

    /// 3.6.2: "This limit is deactivated when the I2T level of the motor falls below 90 %".
    static constexpr double kReleaseLevel = 0.9;
};

/// The output current limitation (ESCON2 FW spec 3.6.2, 6.2.55, 6.2.56): the smallest of
/// - the motor's I²t limit: the output current limit, reduced to the nominal current once the
///   I²t level motor reaches 100 % and until it falls below 90 %;
/// - the power stage's I²t limit, alike;
/// - the temperature limit: from the warning temperature (max − 10 °C, table 95) the output
///   current limit is reduced linearly with the power stage temperature, to 0 at the maximum
///   (where the thermal power stage overload error disables the device).
class OutputCurrentLimitation {
public:
    OutputCurrentLimitation() : OutputCurrentLimitation(CurrentLimitationParameters{}) {}
    explicit OutputCurrentLimitation(const CurrentLimitationParameters& parameters);

    /// New parameters; winding and power stage keep their heat.
    void set_parameters(const CurrentLimitationParameters& parameters);
    /// The output current (A, either sign) during the last `dt` s and the power stage
    /// temperature (°C) now.
    void update(double current, double power_stage_temperature, double dt);

    /// The current limit in force, A.
    double limit() const;
    /// A reduction is in force: statusword bit 11 "internal limit active" (table 104), the
    /// Limitation digital output.
    bool limiting() const;
    /// 0x3200 sub 1 / 0x3201 sub 1 as a fraction (1 = 100 %, more is possible).
    double motor_level() const { return motor_.level(); }
    double power_stage_level() const { return power_stage_ ? power_stage_->level() : 0; }
    /// The temperature's share of the output current limit (1 below the warning temperature).
    double temperature_derating() const { return derating_; }

private:
    CurrentLimitationParameters parameters_;
    motion::I2tCurrentLimit motor_;
    std::optional<motion::I2tCurrentLimit> power_stage_;
    double derating_ = 1;
};

/// 6.2.56.2, table 95: the fraction of the output current limit left at `temperature`: 1 up to
/// the warning temperature (max − 10 °C), falling linearly to 0 at `max_temperature`.
double power_stage_temperature_derating(double temperature, double max_temperature);

/// The warning temperature of table 95.
inline constexpr double kPowerStageWarningMargin = 10; ///< °C below the maximum

} // namespace eposp::drives::escon2
