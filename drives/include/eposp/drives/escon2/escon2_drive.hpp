#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/drives/escon2/error_handling.hpp"
#include "eposp/drives/escon2/escon2_dictionary.hpp"
#include "eposp/drives/escon2/io/pwm_input.hpp"
#include "eposp/drives/escon2/protection/output_current_limitation.hpp"
#include "eposp/drives/escon2/protection/power_supply_supervision.hpp"
#include "eposp/drives/escon2/protection/system_load_supervision.hpp"
#include "eposp/drives/escon2/protection/thermal_supervision.hpp"
#include "eposp/drives/motion/device_control.hpp"
#include "eposp/drives/motion/sensor_direction_monitor.hpp"
#include "eposp/drives/motion/sensor_supervision.hpp"
#include "eposp/drives/motion/trajectory.hpp"
#include "eposp/drives/plant/low_pass_filter.hpp"
#include "eposp/drives/plant/reference_axis.hpp"
#include "eposp/drives/plant/servo_axis.hpp"
#include "eposp/drives/plant/shaft_sensors.hpp"
#include "eposp/drives/plant/thermal_model.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

namespace eposp::drives::escon2 {

class Escon2Io;
struct IoReaction;

/// ESCON2 FW spec table 100: the modes of operation (0x6060).
enum class OperatingMode : std::int8_t { IoVelocity = -121, IoCurrent = -120 };

struct Escon2DriveConfig {
    Escon2DictionaryConfig dictionary;
    /// Motor, load, power stage, encoder pulses and controller gains. The pulses, gains, output
    /// current limit, pole pairs and motor type become the defaults of 0x3010, 0x30A0, 0x30A2,
    /// 0x3001 and 0x6402; the dictionary configures the plant from then on.
    plant::AxisParameters axis = plant::reference_axis();
    /// The power stage's heat path and its conduction losses (I²·R): the manual gives no
    /// figures; these let the Module's 30 A nominal current settle about 60 °C above ambient
    /// within minutes, below the warning temperature of table 95 at 25 °C ambient.
    plant::ThermalParameters power_stage_thermal{
        .ambient_temperature = 25, .thermal_resistance = 3.3, .time_constant = 60};
    double power_stage_loss_resistance = 0.02; ///< Ω
};

/// A simulated maxon ESCON2: its dictionary, the device control of 2.2 (StateMachine::Escon2),
/// I/O Velocity Mode and I/O Current Mode (chapter 3) on the shared ServoAxis plant, the inputs
/// and outputs of chapter 4, the output current limitation (3.6.2) and the error handling of
/// 7.1 with the sensor supervision of 7.1.22 - 7.1.24, stepped by one event-loop timer
/// every millisecond (velocity loop, then ten 0.1 ms current-loop and plant steps) on its own
/// clock, so that a run in virtual time is exact and reproducible.
///
/// The ESCON2 has no CAN: a host (the USB service interface, a test) reads and writes its
/// dictionary; the controlword, the mode and the commanding objects act through change listeners
/// from the next control period on. The set values come from the inputs (analog, PWM, set value
/// switches) or from a host through the set_* methods below, which write the commanding objects
/// of tables 15 and 21; drive enable and quick stop inputs act as device commands.
///
/// Neither copyable nor movable: the dictionary's listeners refer to it.
class Escon2Drive {
public:
    static constexpr std::chrono::microseconds kControlPeriod{1000};

    Escon2Drive(core::EventLoop& loop, Escon2DriveConfig config);
    ~Escon2Drive();
    Escon2Drive(const Escon2Drive&) = delete;
    Escon2Drive& operator=(const Escon2Drive&) = delete;

    /// Power-up: the stored parameters (a refused store raises 0x6380 and keeps the defaults),
    /// the device control through transitions 0 and 1 to «Switch on disabled».
    void start();

    canopen::ObjectDictionary& objects() { return dictionary_.objects(); }
    const canopen::ObjectDictionary& objects() const { return dictionary_.objects(); }
    canopen::ParameterStore& store() { return dictionary_.store(); }
    motion::DriveState state() const { return device_control_.state(); }
    const plant::ServoAxis& axis() const { return axis_; }

    // The commanding parameters (tables 15, 21), in the objects' units; what an input
    // functionality (analog, PWM, set value switches) sets.

    /// Target velocity 0x60FF, velocity units (0x60A9).
    void set_velocity_set_value(std::int32_t velocity);
    /// Velocity offset 0x60B1, velocity units.
    void set_velocity_offset(std::int32_t velocity);
    /// Target current 0x30F0, mA.
    void set_current_set_value(std::int32_t milliamperes);
    /// Current offset 0x30F1, mA.
    void set_current_offset(std::int32_t milliamperes);

    // The pins (chapter 4), driven from outside (a test, a wiring to another device's outputs):
    // the I/O classes of io/ read them as 0x3141 - 0x3172 configure them.

    /// Digital input `input` (1 - 4 regular, 5 - 8 high-speed 1 - 4) high or low from now on;
    /// it counts once held longer than its filter time (4.1.1). Another number is a programming
    /// error (std::out_of_range).
    void set_digital_input(unsigned input, bool high);
    /// The filtered level of digital input `input` as 0x3141 sub 1 shows it.
    bool digital_input(unsigned input) const;
    /// A steady PWM signal at digital input 1 or 2 (6.2.31, 6.2.32); none: the pin's level.
    void set_pwm_signal(unsigned input, std::optional<PwmSignal> signal);
    /// The voltage at analog input 1 or 2 (V), limited to the hardware's range.
    void set_analog_input(unsigned input, double volts);
    /// The level of digital output `output` (1, 2, 3 = high-speed 1) after its polarity.
    bool digital_output(unsigned output) const;
    /// The voltage of analog output 1 or 2, V.
    double analog_output(unsigned output) const;

    /// The air around the device (°C): the power stage cools to it, the logic section is at it
    /// (6.2.12, 6.2.56.2).
    void set_ambient_temperature(double celsius);

    /// The simulated power supply (0x2200 sub 1), supervised against 0x2201 (6.2.11).
    void set_supply_voltage(double volts);
    /// The share of its processor the device's tasks would take (1: all of it), a cause set
    /// from outside as the supply voltage is: from 0.9 on the system overloaded warning, above 1
    /// the system peak overloaded error, and above 1 for 100 ms a watchdog reset (7.1.36 -
    /// 7.1.40; SystemLoadSupervision).
    void set_system_load(double share) { system_load_.set_load(share); }
    /// Raises an error or warning of table 110 as if its cause had occurred: its history entry,
    /// its register bits and error code, and its reaction ("f" quick stop, "d" disable, "w"
    /// warning only). A code the table does not list is a programming error
    /// (std::invalid_argument).
    void raise_device_error(std::uint16_t code);
    /// The cause of an auto-clearing warning went away.
    void clear_warning(std::uint16_t code);
    /// Faults of the motor's sensors from the next control period on (none: all false): the
    /// Hall pattern 0x301A sub 2 reads as the faults make it, and the sensor supervision raises
    /// what it finds (7.1.22 - 7.1.24, docs/escon2.md "Sensor errors").
    void inject_sensor_faults(const plant::SensorFaults& faults) { sensor_faults_ = faults; }
    /// A short of the motor winding against ground (or Vcc, a damaged power stage) from now on
    /// (false: repaired): the power stage protection finds it once the power stage drives the
    /// motor (7.1.4, 0x2320), as on the EPOS2 (Epos2Drive::short_motor_winding).
    void short_motor_winding(bool shorted) { winding_shorted_ = shorted; }

private:
    static Escon2DictionaryConfig with_power_disable_rule(Escon2DictionaryConfig config,
                                                          const Escon2Drive& drive);
    bool power_disabled() const;
    void configure_axis();
    void watch_dictionary();
    void compute_measured_values();
    void on_controlword(std::uint16_t controlword);
    void on_mode_written();
    void control_period();
    void react_to_inputs(const IoReaction& reaction);
    void supervise();
    void watchdog_reset();
    void watch_sensors();
    void read_sensor_configuration();
    void restart_sensor_supervision();
    void update_fault_condition();
    double logic_section_temperature() const;
    double pwm_duty_cycle() const;
    double max_duty_cycle() const;
    void command(std::uint16_t device_command);
    void follow_power_stage();
    void calibrate_current_offset();
    void check_configuration();
    plant::AxisDemand stop_ramp(double now);
    plant::AxisDemand velocity_mode(double now);
    plant::AxisDemand current_mode();
    void publish();
    std::uint16_t statusword() const;

    double seconds() const;
    double counts_per_rpm() const;
    double velocity_unit_in_rpm() const;
    double to_counts(double velocity_units) const;
    double to_velocity_units(double counts_per_second) const;
    double polarity() const;
    bool has_main_sensor() const;

    core::EventLoop& loop_;
    Escon2Dictionary dictionary_;
    plant::AxisParameters machine_;
    plant::ServoAxis axis_;
    motion::DeviceControl device_control_;
    ErrorHandling errors_;
    OutputCurrentLimitation limitation_;
    PowerSupplySupervision supply_;
    ThermalSupervision thermal_;
    SystemLoadSupervision system_load_;
    plant::ThermalModel power_stage_;
    double power_stage_loss_resistance_;
    double ambient_temperature_;
    std::unique_ptr<Escon2Io> io_;
    motion::SensorSupervision sensor_supervision_;    ///< 7.1.22 - 7.1.24
    motion::SensorDirectionMonitor sensor_direction_; ///< 7.1.27
    bool direction_supervision_ = false; ///< the encoder is the main sensor and supervised
    plant::SensorFaults sensor_faults_;  ///< injected
    bool winding_shorted_ = false;       ///< injected (7.1.4)

    OperatingMode mode_ = OperatingMode::IoVelocity;
    std::uint16_t controlword_ = 0;
    bool power_stage_on_ = false;
    /// I/O Velocity Mode's ramp (3.3: profile acceleration / deceleration) toward its target.
    motion::Trajectory ramp_;
    double ramp_start_ = 0;
    double ramp_target_ = 0;     ///< counts/s
    motion::MotionState demand_; ///< of the last control period, counts
    /// A stop ramp of the device control in progress (quick stop, disable operation, "f").
    std::optional<motion::Trajectory> stop_;
    double stop_start_ = 0;
    bool stop_completed_ = false;    ///< the device control has heard that the ramp ended
    bool set_value_limited_ = false; ///< bit 11: max motor speed or output current limit
    /// 6.2.21.1 / 6.2.23.1: the current filtered at 50 Hz every 0.1 ms, the velocity at 5 Hz
    /// every ms.
    plant::LowPassFilter current_averaged_{50, plant::ServoAxis::kCurrentLoopPeriod};
    plant::LowPassFilter velocity_averaged_{5, plant::ServoAxis::kOuterLoopPeriod};
    core::TimePoint control_time_;
    core::ScopedTimer control_timer_;
};

} // namespace eposp::drives::escon2
