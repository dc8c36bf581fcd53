#pragma once

#include "eposp/drives/plant/controller_gains.hpp"
#include "eposp/drives/plant/motor_model.hpp"
#include "eposp/drives/plant/pid_controller.hpp"
#include "eposp/drives/plant/shaft_sensors.hpp"

#include <cstdint>
#include <limits>

namespace eposp::drives::plant {

/// Which loop closes around the current controller (EPOS2 FW spec 5.9, 5.12, 5.14): position
/// and velocity control each output a current demand; the power stage off runs no loop.
enum class ControlMode { PowerOff, Current, Velocity, Position };

/// The demand of the trajectory generator or the operating mode, in drive units: quadcounts,
/// quadcounts/s, quadcounts/s² and amperes.
struct AxisDemand {
    double position = 0;
    double velocity = 0;     ///< velocity demand, and velocity feed-forward in position mode
    double acceleration = 0; ///< acceleration feed-forward
    double current = 0;      ///< current mode only
    /// Current mode: the velocity controller caps the current so that |velocity| stays below
    /// this (quadcounts/s; EPOS2 FW spec 8.2.130 sub 4 "Maximal Motor Speed"); 0: no cap.
    double speed_limit = 0;
};

struct ServoGains {
    CurrentGains current;
    VelocityGains velocity;
    PositionGains position;
    double current_limit = 1; ///< A, the output current limit the outer loops may demand
};

/// Where the machine's encoder sits and which way it counts (the machine file's `encoder`).
struct EncoderMounting {
    /// On the gearhead's output shaft (EPOS2 FW spec 8.2.74: where the main sensor must be with a
    /// gear configured): it turns once per gearhead ratio motor turns.
    bool on_gear_output = false;
    /// Mounted the other way round: it counts down while the motor turns positive (CCW).
    bool counts_against_motor = false;
};

/// How the firmware reads its encoder, as its dictionary configures it.
struct EncoderReading {
    bool inverted = false; ///< 0x2210 sub 4 bit 0 (table 8-104): the counts are negated
    /// Motor turns per encoder turn: 0x2230 sub 1 / sub 2 with a gear configured (8.2.74: the
    /// encoder is then on the gear's output), 1 without. The loops close on motor-shaft radians.
    double gear_ratio = 1;
};

struct AxisParameters {
    PlantParameters plant;
    int encoder_pulses = 500; ///< 0x2210 pulses per turn of the encoder's shaft
    ServoGains gains;
    /// Limit and home switches along the axis, in quadcounts of the encoder's shaft counted in
    /// the motor's positive direction (whichever way the encoder counts).
    SwitchLayout switches;
    EncoderMounting encoder_mounting; ///< the machine's
    EncoderReading encoder_reading;   ///< the firmware's
};

/// One axis: motor model, encoder and the cascade at the EPOS2's rates. The current loop and
/// the plant step at 10 kHz (0.1 ms, the sampling time of 8.2.47); position and velocity loops
/// every tenth step (1 kHz), measuring velocity as quadcounts per millisecond as the EPOS2 does
/// (8.2.48).
class ServoAxis {
public:
    static constexpr double kCurrentLoopPeriod = 100e-6;
    static constexpr int kCurrentStepsPerOuterLoop = 10;
    static constexpr double kOuterLoopPeriod = kCurrentLoopPeriod * kCurrentStepsPerOuterLoop;

    explicit ServoAxis(const AxisParameters& parameters);

    /// New parameters while running (gains, encoder, motor data or the supply written later):
    /// the shaft keeps its state and the controllers their integrals; the encoder counts the same
    /// angle at its new resolution.
    void reconfigure(const AxisParameters& parameters);
    const AxisParameters& parameters() const { return parameters_; }

    /// Switching modes restarts the controllers (their integrators start from zero).
    void set_mode(ControlMode mode);
    ControlMode mode() const { return mode_; }
    void set_demand(const AxisDemand& demand) { demand_ = demand; }
    /// A current limit below the configured output current limit (the drive's I²t limitation,
    /// EPOS2 FW spec 5.14.1), from the next step on; the configured limit applies when larger.
    void reduce_current_limit(double amperes);

    /// One 0.1 ms step of the current loop and the plant. Always inline: a drive runs ten in a
    /// row every control period, the call and its register saves cost about as much as the
    /// current loop's arithmetic, and GCC at -O2 does not inline it by itself.
    [[gnu::always_inline]] void step() {
        if (steps_until_outer_loop_ == 0) {
            run_outer_loop();
            steps_until_outer_loop_ = kCurrentStepsPerOuterLoop;
        }
        --steps_until_outer_loop_;
        if (mode_ == ControlMode::PowerOff) {
            motor_.step_unpowered();
        } else {
            const double error = current_demand_ - motor_.state().current;
            motor_.step(current_controller_.update(error, kCurrentLoopPeriod));
        }
        position_ = quadcounts(encoder_angle(), parameters_.encoder_pulses);
        index_passed_ = !revolution_.holds(position_);
        if (index_passed_) {
            revolution_ = revolution_of(position_, parameters_.encoder_pulses);
        }
    }

    /// The encoder's counts as the firmware reads them (EncoderReading), quadcounts.
    std::int64_t position_actual() const { return position_; }
    double velocity_actual() const { return velocity_; } ///< quadcounts/s over the last 1 ms
    double current_actual() const { return motor_.state().current; }
    double current_demand() const { return current_demand_; }
    /// The angle the firmware's encoder reading stands for: the encoder's shaft (the motor's or
    /// the gear output's) turned the way the encoder counts, negated when the reading inverts
    /// it; position_actual() is its quadcounts. What the sensor supervision reads.
    double encoder_angle() const { return encoder_sign_ * encoder_shaft_angle(); }
    bool index_passed() const { return index_passed_; } ///< during the last step
    std::uint8_t hall_sensors() const;
    /// The switches at the present position, for the digital inputs. A function of the shaft's
    /// angle and the parameters alone, read several times per control period between two steps:
    /// kept for the angle it was computed at (equal doubles are one value, or ±0, which both
    /// quantise to count 0), forgotten when the parameters change.
    SwitchStates switches() const {
        const double angle = encoder_shaft_angle();
        if (angle != switches_angle_) {
            switches_ =
                switch_states(parameters_.switches, quadcounts(angle, parameters_.encoder_pulses));
            switches_angle_ = angle;
        }
        return switches_;
    }
    const MotorModel& motor() const { return motor_; }
    MotorModel& motor() { return motor_; }

private:
    /// The angle of the shaft the encoder sits on, in the motor's direction.
    double encoder_shaft_angle() const {
        return parameters_.encoder_mounting.on_gear_output ? motor_.output_angle()
                                                           : motor_.state().angle;
    }
    void run_outer_loop();
    double cap_at_speed_limit(double current);
    void reset_controllers();
    void apply_current_limit();

    AxisParameters parameters_;
    MotorModel motor_;
    double radians_per_count_; ///< motor-shaft radians per count, as the firmware reads them
    double encoder_sign_;      ///< -1 where the mounting or the reading (not both) inverts
    PidController current_controller_;
    PidController velocity_controller_;
    PidController position_controller_;
    ControlMode mode_ = ControlMode::PowerOff;
    AxisDemand demand_;
    double current_demand_ = 0;
    bool speed_limiting_ = false;      ///< current mode: the velocity controller holds the limit
    double reduced_current_limit_ = 0; ///< reduce_current_limit(), 0: none
    double current_limit_ = 0;         ///< in force: the smaller of the two
    std::int64_t position_ = 0;
    /// switches() at switches_angle_; NaN equals no angle, so that the first call computes.
    mutable double switches_angle_ = std::numeric_limits<double>::quiet_NaN();
    mutable SwitchStates switches_;
    /// The revolution position_ lies in: the index test of every step is two comparisons, the
    /// divisions only when the shaft enters another revolution.
    Revolution revolution_;
    std::int64_t position_at_outer_loop_ = 0;
    double velocity_ = 0;
    bool index_passed_ = false;
    int steps_until_outer_loop_ = 0;
};

} // namespace eposp::drives::plant
