#include "eposp/drives/escon2/protection/output_current_limitation.hpp"

#include <algorithm>
#include <cmath>

namespace eposp::drives::escon2 {

double power_stage_temperature_derating(double temperature, double max_temperature) {
    return std::clamp((max_temperature - temperature) / kPowerStageWarningMargin, 0.0, 1.0);
}

OutputCurrentLimitation::OutputCurrentLimitation(const CurrentLimitationParameters& parameters)
    : parameters_(parameters), motor_(parameters.motor) {
    if (parameters.power_stage) {
        power_stage_.emplace(*parameters.power_stage);
    }
}

void OutputCurrentLimitation::set_parameters(const CurrentLimitationParameters& parameters) {
    parameters_ = parameters;
    motor_.set_parameters(parameters.motor);
    if (!parameters.power_stage) {
        power_stage_.reset();
    } else if (power_stage_) {
        power_stage_->set_parameters(*parameters.power_stage);
    } else {
        power_stage_.emplace(*parameters.power_stage);
    }
}

void OutputCurrentLimitation::update(double current, double power_stage_temperature, double dt) {
    motor_.update(current, dt);
    if (power_stage_) {
        power_stage_->update(current, dt);
    }
    derating_ = power_stage_temperature_derating(power_stage_temperature,
                                                 parameters_.max_power_stage_temperature);
}

double OutputCurrentLimitation::limit() const {
    double limit = std::min(motor_.limit(), derating_ * parameters_.motor.output_current_limit);
    if (power_stage_) {
        limit = std::min(limit, power_stage_->limit());
    }
    return limit;
}

bool OutputCurrentLimitation::limiting() const {
    return motor_.limiting() || (power_stage_ && power_stage_->limiting()) || derating_ < 1;
}

} // namespace eposp::drives::escon2
