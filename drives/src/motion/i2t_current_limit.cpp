#include "eposp/drives/motion/i2t_current_limit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace eposp::drives::motion {
namespace {

plant::ThermalParameters normalised_winding(const I2tParameters& parameters) {
    return {.ambient_temperature = 0,
            .thermal_resistance = 1,
            .time_constant = parameters.time_constant};
}

} // namespace

I2tCurrentLimit::I2tCurrentLimit(const I2tParameters& parameters)
    : parameters_(parameters), winding_(normalised_winding(parameters)) {}

void I2tCurrentLimit::set_parameters(const I2tParameters& parameters) {
    parameters_ = parameters;
    winding_.set_parameters(normalised_winding(parameters));
}

// No continuous current at all: limited to 0 at once.
void I2tCurrentLimit::hold_without_continuous_current(double current) {
    winding_.set_temperature(current == 0 ? 0 : 1);
    limiting_ = current != 0;
}

double I2tCurrentLimit::limit() const {
    return limiting() ? std::min(parameters_.continuous_current, parameters_.output_current_limit)
                      : parameters_.output_current_limit;
}

double peak_current_duration(double normalised_peak, double time_constant) {
    if (normalised_peak <= 1) {
        return std::numeric_limits<double>::infinity();
    }
    return -time_constant * std::log1p(-1 / (normalised_peak * normalised_peak));
}

double thermal_time_constant(double peak_current, double peak_duration, double nominal_current) {
    if (!(peak_current > nominal_current) || !(nominal_current > 0)) {
        throw std::invalid_argument("the peak current must exceed a positive nominal current");
    }
    const double ratio = nominal_current / peak_current;
    return -peak_duration / std::log1p(-ratio * ratio);
}

double max_cyclic_on_current(double duty_cycle, double total_time, double time_constant) {
    if (!(duty_cycle > 0) || duty_cycle > 1 || !(total_time > 0) || !(time_constant > 0)) {
        throw std::invalid_argument("a cyclic current needs a duty cycle in (0, 1] and positive "
                                    "times");
    }
    return std::sqrt(std::expm1(-total_time / time_constant) /
                     std::expm1(-duty_cycle * total_time / time_constant));
}

} // namespace eposp::drives::motion
