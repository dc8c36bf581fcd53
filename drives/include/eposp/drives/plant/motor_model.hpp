#pragma once

#include "eposp/core/result.hpp"

#include <algorithm>
#include <cmath>

namespace eposp::drives::plant {

/// Motor Type 0x6402 families the model covers.
enum class MotorKind {
    BrushedDc,
    Ec, ///< brushless, ideally commutated: the terminal (phase-to-phase) data of maxon's sheets
};

/// A motor as maxon's data sheets describe it, in SI units.
struct MotorParameters {
    MotorKind kind = MotorKind::BrushedDc;
    double terminal_resistance = 0; ///< Ω
    double terminal_inductance = 0; ///< H
    double torque_constant = 0;     ///< N·m/A
    double speed_constant = 0;      ///< rpm/V
    int pole_pairs = 1;             ///< EC only
    double rotor_inertia = 0;       ///< kg·m²

    /// Back-EMF constant in V·s/rad, from the speed constant.
    double back_emf_constant() const;
};

/// What the shaft drives, on the output side of the gearhead.
struct LoadParameters {
    double inertia = 0;          ///< kg·m²
    double viscous_friction = 0; ///< N·m·s/rad
    double coulomb_friction = 0; ///< N·m
};

/// An optional gearhead; ratio 1 and efficiency 1 is a direct drive.
struct GearheadParameters {
    double ratio = 1;      ///< motor turns per output turn
    double efficiency = 1; ///< applied to the load torques the motor must overcome
};

/// The power stage: PWM duty limits of the supply voltage, and the limits its supervision trips
/// at. The EPOS2 FW spec (4.2.3, 4.2.5, 4.2.6) names the errors but not their thresholds; the
/// defaults are the EPOS2 24/5's absolute operating range of +VCC (9 ... 26 V) and 1.5 times its
/// 10 A maximal output current.
struct PowerStageParameters {
    double supply_voltage = 24;     ///< V
    double max_duty = 0.9;          ///< fraction of the supply the bridge can apply
    double min_supply_voltage = 9;  ///< V; below: undervoltage 0x3220
    double max_supply_voltage = 26; ///< V; above: overvoltage 0x3210
    double overcurrent = 15;        ///< A of motor current; above: overcurrent 0x2310
    double max_voltage() const { return supply_voltage * max_duty; }
};

struct PlantParameters {
    MotorParameters motor;
    LoadParameters load;
    GearheadParameters gearhead;
    PowerStageParameters power_stage;
};

/// The parameters unchanged, or which of them makes the model meaningless (a zero resistance,
/// inductance, constant or inertia, a gear ratio or efficiency out of range, negative friction).
/// MotorModel requires parameters that pass.
core::Result<PlantParameters> validate(const PlantParameters& parameters);

/// The electrical and mechanical state of the motor shaft.
struct MotorState {
    double current = 0; ///< A
    double speed = 0;   ///< motor shaft, rad/s
    double angle = 0;   ///< motor shaft, rad
};

/// The motor, gearhead and load seen from the motor shaft, integrated with a fixed step.
///
/// Solver: the RL circuit is discretised exactly for a voltage held over the step (the PWM
/// average is held for a control period, and the back-EMF barely changes in 100 µs). Explicit
/// Euler would be unstable once the step exceeds 2·L/R, and maxon's small motors have L/R of
/// ~0.1 ms, the size of the step. The mechanical part (time constants of milliseconds) takes the
/// step's mean current, with viscous friction implicit and Coulomb friction that sticks.
class MotorModel {
public:
    /// `step` is the fixed integration step in seconds; the exponentials of the electrical
    /// solution depend only on it and are computed once.
    MotorModel(const PlantParameters& parameters, double step);

    /// Applies `voltage` (clamped to ±max voltage of the power stage) for one step.
    void step(double voltage);
    /// The power stage switched off: the bridge is open, the current decays to zero at once (the
    /// free-wheeling time is far below a step) and the shaft coasts.
    void step_unpowered();

    const MotorState& state() const { return state_; }
    void set_state(const MotorState& state) { state_ = state; }
    const PlantParameters& parameters() const { return parameters_; }

    /// Inertia, friction and their combination seen at the motor shaft.
    double reflected_inertia() const { return inertia_; }
    /// The output-side angle (after the gearhead), rad.
    double output_angle() const;

private:
    void integrate_mechanics(double mean_current);

    PlantParameters parameters_;
    double step_;
    double current_decay_ = 0;       ///< e^(−step·R/L)
    double mean_current_weight_ = 0; ///< (1 − e^(−step·R/L))/(step·R/L)
    MotorState state_;
    double inertia_ = 0;
    double viscous_ = 0;
    double coulomb_ = 0;
    double back_emf_constant_ = 0;
    double step_over_inertia_ = 0;
    double viscous_decay_ = 0; ///< implicit Euler factor 1/(1 + step·b/J)
};

// Inline: the current loop steps every motor ten times per control period.
inline void MotorModel::step(double voltage) {
    const double limit = parameters_.power_stage.max_voltage();
    const double applied = std::clamp(voltage, -limit, limit);
    // i' = (u − e − R·i)/L with u and e held: i → i_final exponentially with τ = L/R.
    const double i_final =
        (applied - back_emf_constant_ * state_.speed) / parameters_.motor.terminal_resistance;
    const double i_start = state_.current;
    state_.current = i_final + (i_start - i_final) * current_decay_;
    // The exact mean of that exponential over the step drives the shaft.
    integrate_mechanics(i_final + (i_start - i_final) * mean_current_weight_);
}

inline void MotorModel::integrate_mechanics(double mean_current) {
    const double drive = parameters_.motor.torque_constant * mean_current;
    const double omega = state_.speed;
    if (omega == 0 && std::abs(drive) <= coulomb_) {
        return; // static friction holds the shaft
    }
    const double direction = omega != 0 ? std::copysign(1.0, omega) : std::copysign(1.0, drive);
    double next = (omega + step_over_inertia_ * (drive - coulomb_ * direction)) * viscous_decay_;
    if (next * direction < 0 && std::abs(drive) <= coulomb_) {
        next = 0; // friction brings the shaft to rest, it does not reverse it
    }
    state_.angle += 0.5 * (omega + next) * step_;
    state_.speed = next;
}

} // namespace eposp::drives::plant
