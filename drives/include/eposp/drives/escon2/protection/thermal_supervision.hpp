#pragma once

#include "eposp/drives/escon2/protection/device_error_code.hpp"

#include <vector>

namespace eposp::drives::escon2 {

/// Max temperature power stage 0x3201 sub 3 and the logic section's limit and hysteresis of
/// tables 45 / 46, °C; the defaults are the ESCON2 Module 60/30's.
struct ThermalLimits {
    double max_power_stage_temperature = 110;
    double logic_section_limit = 108;
    double logic_section_hysteresis = 10;
};

/// The temperature supervision (ESCON2 FW spec 6.2.12, 6.2.56.2, 6.2.56.3, 7.1.8 - 7.1.10):
/// - above the warning temperature (max − 10 °C, table 95) the thermal power stage overload
///   warning, while the output current is reduced, cleared once below it again;
/// - at Max temperature power stage the thermal power stage overload error, present until the
///   temperature has fallen below it;
/// - above the logic section limit the thermal logic section overload error, present until the
///   temperature drops below limit − hysteresis.
/// The temperatures come from the thermal models (plant::ThermalModel) the drive steps.
class ThermalSupervision {
public:
    ThermalSupervision() = default;
    explicit ThermalSupervision(const ThermalLimits& limits) : limits_(limits) {}

    void set_limits(const ThermalLimits& limits) { limits_ = limits; }
    /// The temperatures (°C) now.
    void update(double power_stage_temperature, double logic_section_temperature);

    bool power_stage_warning() const { return power_stage_warning_; }
    bool power_stage_error() const { return power_stage_error_; }
    bool logic_section_error() const { return logic_section_error_; }
    /// The present conditions as error codes (table 110).
    std::vector<DeviceErrorCode> conditions() const;

private:
    ThermalLimits limits_;
    bool power_stage_warning_ = false;
    bool power_stage_error_ = false;
    bool logic_section_error_ = false;
};

} // namespace eposp::drives::escon2
