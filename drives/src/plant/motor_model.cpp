#include "eposp/drives/plant/motor_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eposp::drives::plant {

double MotorParameters::back_emf_constant() const {
    return 60.0 / (2 * std::numbers::pi * speed_constant);
}

core::Result<PlantParameters> validate(const PlantParameters& parameters) {
    const MotorParameters& motor = parameters.motor;
    if (!(motor.terminal_resistance > 0) || !(motor.terminal_inductance > 0)) {
        return core::Error{"motor terminal resistance and inductance must be positive"};
    }
    if (!(motor.torque_constant > 0) || !(motor.speed_constant > 0)) {
        return core::Error{"motor torque and speed constants must be positive"};
    }
    if (!(motor.rotor_inertia > 0) || motor.pole_pairs < 1) {
        return core::Error{"rotor inertia must be positive and pole pairs at least 1"};
    }
    const LoadParameters& load = parameters.load;
    if (!(load.inertia >= 0) || !(load.viscous_friction >= 0) || !(load.coulomb_friction >= 0)) {
        return core::Error{"load inertia and friction must not be negative"};
    }
    const GearheadParameters& gearhead = parameters.gearhead;
    if (!(gearhead.ratio > 0) || !(gearhead.efficiency > 0) || gearhead.efficiency > 1) {
        return core::Error{"gear ratio must be positive and efficiency in (0, 1]"};
    }
    const PowerStageParameters& stage = parameters.power_stage;
    if (!(stage.supply_voltage > 0) || !(stage.max_duty > 0) || stage.max_duty > 1) {
        return core::Error{"supply voltage must be positive and max PWM duty in (0, 1]"};
    }
    if (!(stage.min_supply_voltage < stage.max_supply_voltage) || !(stage.overcurrent > 0)) {
        return core::Error{"the undervoltage limit must lie below the overvoltage limit and the "
                           "overcurrent limit must be positive"};
    }
    return parameters;
}

MotorModel::MotorModel(const PlantParameters& parameters, double step)
    : parameters_(parameters), step_(step),
      back_emf_constant_(parameters.motor.back_emf_constant()) {
    const double x =
        step * parameters.motor.terminal_resistance / parameters.motor.terminal_inductance;
    current_decay_ = std::exp(-x);
    mean_current_weight_ = (1 - current_decay_) / x;
    // Load quantities reflect through the gearhead by 1/N² (inertia, viscous) and 1/(N·η)
    // (Coulomb torque the motor must supply).
    const double ratio = parameters.gearhead.ratio;
    inertia_ = parameters.motor.rotor_inertia + parameters.load.inertia / (ratio * ratio);
    viscous_ = parameters.load.viscous_friction / (ratio * ratio);
    coulomb_ = parameters.load.coulomb_friction / (ratio * parameters.gearhead.efficiency);
    step_over_inertia_ = step / inertia_;
    viscous_decay_ = 1 / (1 + step * viscous_ / inertia_);
}

double MotorModel::output_angle() const {
    return state_.angle / parameters_.gearhead.ratio;
}

void MotorModel::step_unpowered() {
    state_.current = 0;
    integrate_mechanics(0);
}

} // namespace eposp::drives::plant
