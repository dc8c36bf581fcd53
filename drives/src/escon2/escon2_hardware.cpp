#include "eposp/drives/escon2/escon2_hardware.hpp"

namespace eposp::drives::escon2 {
namespace {

// ESCON2 FW spec tables 40 - 46, 53, 54, 71 - 97, one row per hardware.
constexpr HardwareData kModule60_30{
    .product_name = "ESCON2 Module 60/30",
    .hardware_version = 0x1101,
    .undervoltage_limit = {7'500, 7'500, 63'750},
    .undervoltage_hysteresis = 250,
    .overvoltage_limit = {65'000, 8'750, 65'000},
    .overvoltage_hysteresis = 1'000,
    .logic_temperature_limit = 1'080,
    .logic_temperature_hysteresis = 100,
    .nominal_current = {30'000, 0, 30'000},
    .output_current_limit = {60'000, 0, 60'000},
    .analog_output_low = -4'000,
    .analog_output_high = 4'000,
    .analog_input_low = -10'000,
    .analog_input_high = 10'000,
    .max_temperature_power_stage = {1'100, 0, 1'100},
    .power_stage_warning_below_max = 100,
    .pwm_max_duty_cycle = 950,
};

constexpr HardwareData kCompact60_30 = [] {
    HardwareData compact = kModule60_30;
    compact.product_name = "ESCON2 Compact 60/30";
    return compact;
}();

constexpr HardwareData kMicro60_5{
    .product_name = "ESCON2 Micro 60/5",
    .hardware_version = 0x1102,
    .undervoltage_limit = {7'500, 7'500, 63'750},
    .undervoltage_hysteresis = 250,
    .overvoltage_limit = {65'000, 8'750, 65'000},
    .overvoltage_hysteresis = 1'000,
    .logic_temperature_limit = 1'150,
    .logic_temperature_hysteresis = 100,
    .nominal_current = {5'000, 0, 5'000},
    .output_current_limit = {15'000, 0, 15'000},
    .analog_output_low = -4'000,
    .analog_output_high = 4'000,
    .analog_input_low = -10'000,
    .analog_input_high = 10'000,
    .max_temperature_power_stage = {1'000, 0, 1'000},
    .power_stage_warning_below_max = 100,
    .pwm_max_duty_cycle = 950,
};

constexpr HardwareData kNano24_2{
    .product_name = "ESCON2 Nano 24/2",
    .hardware_version = 0x1103,
    .undervoltage_limit = {4'500, 4'500, 29'000},
    .undervoltage_hysteresis = 50,
    .overvoltage_limit = {31'000, 4'550, 31'000},
    .overvoltage_hysteresis = 2'000,
    .logic_temperature_limit = 1'080,
    .logic_temperature_hysteresis = 100,
    .nominal_current = {2'000, 0, 2'000},
    .output_current_limit = {6'000, 0, 6'000},
    .analog_output_low = 0,
    .analog_output_high = 3'300,
    .analog_input_low = 0,
    .analog_input_high = 5'000,
    .max_temperature_power_stage = {900, 0, 900},
    .power_stage_warning_below_max = 100,
    .pwm_max_duty_cycle = 900,
};

} // namespace

const HardwareData& hardware_data(Escon2Hardware hardware) {
    switch (hardware) {
    case Escon2Hardware::Module60_30:
        return kModule60_30;
    case Escon2Hardware::Compact60_30:
        return kCompact60_30;
    case Escon2Hardware::Micro60_5:
        return kMicro60_5;
    case Escon2Hardware::Nano24_2:
        return kNano24_2;
    }
    return kModule60_30;
}

} // namespace eposp::drives::escon2
