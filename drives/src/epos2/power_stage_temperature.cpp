#include "eposp/drives/epos2/power_stage_temperature.hpp"

namespace eposp::drives::epos2 {

void PowerStageTemperature::set_ambient_temperature(double celsius) {
    thermal_.body.ambient_temperature = celsius;
    body_.set_parameters(thermal_.body);
}

void PowerStageTemperature::update(double amperes, bool power_stage_on, double dt) {
    const double losses =
        power_stage_on ? thermal_.idle_losses + amperes * amperes * thermal_.loss_resistance : 0;
    body_.step(losses, dt);
}

} // namespace eposp::drives::epos2
