#pragma once

#include <cstdint>
#include <string_view>

namespace eposp::drives::escon2 {

/// ESCON2 FW spec table 40: the hardware an ESCON2 dictionary describes. Module and Compact
/// 60/30 share hardware version 0x1101 and every hardware-dependent value.
enum class Escon2Hardware { Module60_30, Compact60_30, Micro60_5, Nano24_2 };

/// A hardware-dependent default with its value range, as the manual's "Hardware | Default | Min
/// | Max" tables give it.
struct DefaultAndRange {
    std::int64_t default_value;
    std::int64_t min;
    std::int64_t max;
};

/// One row of every hardware-dependent table of ESCON2 FW spec chapter 6, in the units of the
/// objects (mV, mA, 0.1 °C, 0.1 %).
struct HardwareData {
    std::string_view product_name;
    std::uint16_t hardware_version;              ///< table 40, 0x1018 sub 2 high word
    DefaultAndRange undervoltage_limit;          ///< table 41, 0x2201 sub 1
    std::int64_t undervoltage_hysteresis;        ///< table 42
    DefaultAndRange overvoltage_limit;           ///< table 43, 0x2201 sub 2
    std::int64_t overvoltage_hysteresis;         ///< table 44
    std::int64_t logic_temperature_limit;        ///< table 45, 0.1 °C
    std::int64_t logic_temperature_hysteresis;   ///< table 46, 0.1 °C
    DefaultAndRange nominal_current;             ///< table 53, 0x3001 sub 1
    DefaultAndRange output_current_limit;        ///< table 54, 0x3001 sub 2
    std::int64_t analog_output_low;              ///< tables 71, 84 - 94: range and first point
    std::int64_t analog_output_high;             ///< and second slope point
    std::int64_t analog_input_low;               ///< tables 72 - 83: range and first point
    std::int64_t analog_input_high;              ///< and second slope point
    DefaultAndRange max_temperature_power_stage; ///< table 96, 0x3201 sub 3, 0.1 °C
    std::int64_t power_stage_warning_below_max;  ///< table 95: warning at max − 10 °C
    std::int64_t pwm_max_duty_cycle;             ///< table 97, 0.1 %
};

const HardwareData& hardware_data(Escon2Hardware hardware);

} // namespace eposp::drives::escon2
