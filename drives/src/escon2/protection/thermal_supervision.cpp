#include "eposp/drives/escon2/protection/thermal_supervision.hpp"

#include "eposp/drives/escon2/protection/output_current_limitation.hpp"

namespace eposp::drives::escon2 {

void ThermalSupervision::update(double power_stage_temperature, double logic_section_temperature) {
    const double max = limits_.max_power_stage_temperature;
    power_stage_warning_ = power_stage_temperature > max - kPowerStageWarningMargin;
    power_stage_error_ = power_stage_temperature >= max;
    if (logic_section_temperature > limits_.logic_section_limit) {
        logic_section_error_ = true;
    } else if (logic_section_temperature <
               limits_.logic_section_limit - limits_.logic_section_hysteresis) {
        logic_section_error_ = false;
    }
}

std::vector<DeviceErrorCode> ThermalSupervision::conditions() const {
    std::vector<DeviceErrorCode> codes;
    if (power_stage_error_) {
        codes.push_back(DeviceErrorCode::ThermalPowerStageOverload);
    } else if (power_stage_warning_) {
        codes.push_back(DeviceErrorCode::ThermalPowerStageOverloadWarning);
    }
    if (logic_section_error_) {
        codes.push_back(DeviceErrorCode::ThermalLogicSectionOverload);
    }
    return codes;
}

} // namespace eposp::drives::escon2
