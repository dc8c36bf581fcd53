#include "eposp/drives/escon2/io/analog_outputs.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace eposp::drives::escon2 {

std::optional<AnalogOutputFunction> analog_output_function_from_code(std::uint8_t code) {
    if (code <= 1 || (code >= 8 && code <= 13) || code == 255) {
        return static_cast<AnalogOutputFunction>(code);
    }
    return std::nullopt;
}

AnalogOutputs::AnalogOutputs(double low, double high) : low_(low), high_(high) {
    if (!(high > low)) {
        throw std::invalid_argument("an analog output range needs high > low");
    }
}

void AnalogOutputs::configure(const AnalogOutputConfiguration& config) {
    config_ = config;
}

void AnalogOutputs::write_general_purpose(AnalogOutputFunction which, double volts) {
    if (which != AnalogOutputFunction::GeneralPurposeA &&
        which != AnalogOutputFunction::GeneralPurposeB) {
        throw std::invalid_argument("only general purpose A and B are written by the host");
    }
    general_purpose_[static_cast<unsigned>(which)] = limited(volts);
}

void AnalogOutputs::update(const MonitoredValues& values) {
    values_ = values;
}

double AnalogOutputs::limited(double volts) const {
    return std::clamp(volts, low_, high_);
}

double AnalogOutputs::monitored(AnalogOutputFunction function) const {
    const AnalogOutputScalings& scale = config_.scalings;
    switch (function) {
    case AnalogOutputFunction::GeneralPurposeA:
    case AnalogOutputFunction::GeneralPurposeB:
        return general_purpose_[static_cast<unsigned>(function)];
    case AnalogOutputFunction::VelocityActual:
        return scale.velocity.apply(values_.velocity);
    case AnalogOutputFunction::VelocityActualAveraged:
        return scale.velocity.apply(values_.velocity_averaged);
    case AnalogOutputFunction::CurrentActual:
        return scale.current.apply(values_.current);
    case AnalogOutputFunction::CurrentActualAveraged:
        return scale.current.apply(values_.current_averaged);
    case AnalogOutputFunction::TemperatureLogicSection:
        return scale.logic_section_temperature.apply(values_.logic_section_temperature);
    case AnalogOutputFunction::TemperaturePowerStage:
        return scale.power_stage_temperature.apply(values_.power_stage_temperature);
    case AnalogOutputFunction::None:
        break;
    }
    return 0;
}

double AnalogOutputs::voltage(unsigned output) const {
    if (output < 1 || output > kAnalogOutputCount) {
        throw std::out_of_range("ESCON2 analog output " + std::to_string(output) +
                                " does not exist (1 or 2)");
    }
    return limited(monitored(config_.functions[output - 1]));
}

} // namespace eposp::drives::escon2
