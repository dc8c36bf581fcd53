#include "eposp/drives/plant/thermal_model.hpp"

#include <cmath>
#include <stdexcept>

namespace eposp::drives::plant {

ThermalParameters winding_thermal_parameters(double nominal_current, double resistance,
                                             double time_constant, double max_temperature,
                                             double ambient_temperature) {
    const double nominal_power = nominal_current * nominal_current * resistance;
    if (nominal_power <= 0) {
        throw std::invalid_argument("a winding heats only with a positive current and resistance");
    }
    return {.ambient_temperature = ambient_temperature,
            .thermal_resistance = (max_temperature - ambient_temperature) / nominal_power,
            .time_constant = time_constant};
}

ThermalModel::ThermalModel(const ThermalParameters& parameters)
    : parameters_(parameters), temperature_(parameters.ambient_temperature) {
    set_parameters(parameters);
}

void ThermalModel::set_parameters(const ThermalParameters& parameters) {
    if (!(parameters.time_constant > 0) || !(parameters.thermal_resistance >= 0)) {
        throw std::invalid_argument("a thermal body needs a positive time constant and a "
                                    "non-negative thermal resistance");
    }
    parameters_ = parameters;
    gain_dt_ = 0;
}

void ThermalModel::set_step(double dt) {
    gain_dt_ = dt;
    gain_ = -std::expm1(-dt / parameters_.time_constant);
}

} // namespace eposp::drives::plant
