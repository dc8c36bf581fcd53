#pragma once

#include "eposp/can/port.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/node.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/drives/epos2/epos2_dictionary.hpp"
#include "eposp/drives/epos2/power_stage_temperature.hpp"
#include "eposp/drives/motion/device_control.hpp"
#include "eposp/drives/motion/following_error_monitor.hpp"
#include "eposp/drives/motion/homing_procedure.hpp"
#include "eposp/drives/motion/i2t_current_limit.hpp"
#include "eposp/drives/motion/sensor_direction_monitor.hpp"
#include "eposp/drives/motion/sensor_supervision.hpp"
#include "eposp/drives/motion/software_position_limit.hpp"
#include "eposp/drives/motion/standstill_monitor.hpp"
#include "eposp/drives/motion/system_load.hpp"
#include "eposp/drives/motion/trajectory.hpp"
#include "eposp/drives/plant/low_pass_filter.hpp"
#include "eposp/drives/plant/reference_axis.hpp"
#include "eposp/drives/plant/servo_axis.hpp"
#include "eposp/drives/plant/shaft_sensors.hpp"

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace eposp::drives::epos2 {

class Epos2Io;
class ModeBehaviour;
struct ModeInputs;
struct ModeServices;

/// EPOS2 FW spec 8.2.90, table 8-118: the modes of operation, all simulated (docs/epos2.md).
enum class OperatingMode : std::int8_t {
    ProfilePosition = 1,
    ProfileVelocity = 3,
    Homing = 6,
    InterpolatedPosition = 7,
    Position = -1,
    Velocity = -2,
    Current = -3,
    Diagnostic = -4,
    MasterEncoder = -5,
    StepDirection = -6,
};

/// EPOS2 FW spec 8.2.63: the two analog inputs of 0x207C.
enum class AnalogInput : std::uint8_t { Input1 = 1, Input2 = 2 };

/// EPOS2 FW spec table 8-86: the two limit switch functionalities of the digital inputs.
enum class LimitSwitch { Negative, Positive };

struct Epos2DriveConfig {
    Epos2DictionaryConfig dictionary;
    /// Motor, load, power stage, encoder pulses, switches and the controller gains. The pulses,
    /// gains, motor type, pole pairs and current limit become the defaults of 0x2210, 0x60F6,
    /// 0x60F9, 0x60FB, 0x6402 and 0x6410; the dictionary configures the plant from then on.
    plant::AxisParameters axis = plant::reference_axis();
    /// The power stage's heating for the Overtemperature Error 0x4210.
    PowerStageThermal power_stage_thermal;
};

/// A simulated maxon EPOS2 24/5 on a CAN port: a canopen::Node on the EPOS2 dictionary, the
/// CiA 402 device control with its stop ramps, every mode of table 8-118 (Profile Position,
/// Profile Velocity, Homing, Interpolated Position, Position, Velocity, Current, Diagnostic,
/// Master Encoder and Step/Direction Mode, each a ModeBehaviour in src/epos2/modes/), the I²t
/// current limitation, the analog set values, the digital inputs and outputs with the position
/// marker, position compare and holding brake, and the motor model, stepped on the event loop
/// (EPOS2 FW spec 5.9: current loop every 0.1 ms, position and velocity loops every 1 ms;
/// docs/epos2.md lists each function). The master sees only the dictionary: controlword, mode and
/// profile objects written by SDO or RPDO act through change listeners, and so do the encoder,
/// gains and motor data, which reconfigure the running plant; the computed objects (statusword,
/// actual values, digital inputs) are stored each millisecond when they change, so that SDO,
/// synchronous and event-driven TPDOs read them alike, and the further measured values (encoder
/// counter, averaged values, current demand, following error) are computed when read. The power
/// stage's supervision, the sensor supervision, the CAN controller's error-passive and bus-off
/// states and its lost frames raise their errors of table 4-11.
///
/// Neither copyable nor movable: the dictionary's listeners refer to it.
class Epos2Drive {
public:
    Epos2Drive(core::EventLoop& loop, can::Port& port, Epos2DriveConfig config);
    ~Epos2Drive();
    Epos2Drive(const Epos2Drive&) = delete;
    Epos2Drive& operator=(const Epos2Drive&) = delete;

    /// Power-up: boot-up message, NMT pre-operational, device control in Switch On Disabled.
    void start();

    canopen::Node& node() { return node_; }
    canopen::ObjectDictionary& objects() { return dictionary_.objects(); }
    const canopen::ObjectDictionary& objects() const { return dictionary_.objects(); }
    motion::DriveState state() const { return device_control_.state(); }
    const plant::ServoAxis& axis() const { return axis_; }

    /// The simulated power supply: the drive checks it against the power stage's limits
    /// (undervoltage 0x3220, overvoltage 0x3210) every control period.
    void set_supply_voltage(double volts);
    /// The air around the drive (°C, a hot cabinet): the power stage's temperature follows it
    /// with its time constant; above PowerStageThermal::max_temperature the drive raises 0x4210
    /// and refuses a fault reset until it has cooled below it (4.2.7).
    void set_ambient_temperature(double celsius) {
        power_stage_temperature_.set_ambient_temperature(celsius);
    }
    double power_stage_temperature() const { return power_stage_temperature_.temperature(); }
    /// The share of its processor the drive's tasks would take (motion::SystemLoad, 1: all of
    /// it). Above 1 a target value written with the drive function enabled cannot be processed:
    /// 0xFF0B System Overloaded (4.2.32, "d").
    void set_system_load(double share) { system_load_.set(share); }

    // Digital inputs and outputs of an EPOS2 24/5 (docs/epos2.md, "Digital inputs and outputs").

    /// Drives digital input `input` (1 … 6) high or low from outside the drive: a test, the
    /// network file, an EPOS P output. The machine's switches drive inputs 4 - 6 too (home,
    /// positive, negative limit switch, normally open); a pin is high when any source drives
    /// it. 0x2070 and 0x2071 decide what it means from the next control period on. Another
    /// input number is a programming error (std::invalid_argument).
    void set_digital_input(unsigned input, bool high);
    /// The level of digital input `input` (1 … 6) from every source.
    bool digital_input(unsigned input) const;
    /// The level of digital output `output` (1 … 4) as 0x2078 and 0x2079 make it (8.2.59, 8.2.60).
    bool digital_output(unsigned output) const;
    /// The voltage at an analog input (8.2.63, 0x207C, mV), from the next control period on; an
    /// input configured as a set value (0x207B) and executed (0x207D) commands the Position,
    /// Velocity or Current Mode (8.2.81 - 8.2.83).
    void set_analog_input(AnalogInput input, std::int16_t millivolts);
    /// Counts on the digital position input (inputs 2 and 3, 5.7 / 5.8): the quadrature counter
    /// of a master encoder, or the up/down counter of step pulses, advances by `counts` (negative
    /// counts down). It commands the Master Encoder and Step/Direction Modes; a neighbouring
    /// axis' encoder counts fed here make this axis follow it as an electronic gear.
    void count_digital_position_input(std::int32_t counts) {
        // A 32-bit hardware counter: it wraps.
        digital_position_counter_ =
            static_cast<std::int32_t>(static_cast<std::uint32_t>(digital_position_counter_) +
                                      static_cast<std::uint32_t>(counts));
    }

    // Fault injection (docs/epos2.md, "Fault injection").

    /// Holds a limit switch pressed whatever the axis' position, or lets it go again (then only
    /// the machine's switch layout presses it). Its functionality shows in 0x2071 sub 1 under the
    /// mask (sub 2), homing sees it, and its rising edge in a control period with the power
    /// stage on raises 0xFF06 / 0xFF07 when the execution mask (sub 4) has its bit (8.2.57,
    /// 4.2.27, 4.2.28). Pressing a pressed switch changes nothing.
    void hold_limit_switch(LimitSwitch which, bool pressed);
    /// Raises an error of table 4-11 as if its cause had occurred (4.1): its EMCY, its bits in
    /// 0x1001, a new entry in 0x1003, and the reaction of its class ("d" disables at once, "f"
    /// as 0x605E says, "a" as 0x6007 says); a fault reset clears it. An error still active is
    /// not raised again (one EMCY per error event, CiA 301 7.2.7). A code the table does not
    /// list is a programming error (std::invalid_argument; device_errors() lists them).
    void raise_device_error(std::uint16_t code);
    /// Faults of the motor's sensors from the next control period on (none: all false): the
    /// sensor inputs (0x2022, the index for homing) read as the faults make them, and the sensor
    /// supervision raises what it finds (4.2.23 - 4.2.31, docs/epos2.md "Fault injection").
    /// `supply_overloaded` raises 0x5113 and silences both sensors; the sensor supervision rests
    /// while it lasts, and a fault reset is refused until it is repaired (4.2.8).
    void inject_sensor_faults(const plant::SensorFaults& faults) { sensor_faults_ = faults; }
    /// A short in the motor winding (or to earth), or repaired: while the power stage drives the
    /// motor its driver reports it, 0x2320 (4.2.4, "d"); a fault reset is allowed, and enabling
    /// again trips again while the short lasts.
    void short_motor_winding(bool shorted) { winding_shorted_ = shorted; }

private:
    static Epos2DictionaryConfig with_restore_rule(Epos2DictionaryConfig config, Epos2Drive& drive);
    void configure_axis();
    void watch_power_stage(bool overcurrent);
    void watch_sensors();
    void watch_bus_queues();
    void read_sensor_configuration();
    void restart_sensor_supervision();
    void clear_errors();
    void reset_actual_position();
    bool commutation_resolution_too_low() const;
    std::optional<std::uint16_t> supply_error() const;
    bool fault_condition_present() const;
    /// The same, with the supply error and the power stage's temperature already read.
    bool fault_condition_present(const std::optional<std::uint16_t>& supply, bool too_hot) const;
    void watch_dictionary();
    void compute_measured_values();
    void reset_application();
    void on_controlword(std::uint16_t controlword);
    void handle_pending_controlwords(); ///< in the order written
    void on_mode_written();
    void on_error_recorded();
    void control_period();
    void follow_power_stage();
    void finish_device_control_transitions();
    motion::MotionState stop_ramp(double now);
    ModeInputs mode_inputs() const;
    void watch_motion(const motion::MotionState& demand);
    void watch_io(double now);
    /// The machine's switches at the present position, and those held by hold_limit_switch().
    plant::SwitchStates switches() const;
    void publish(const motion::MotionState& demand);
    std::uint16_t statusword() const;
    std::uint16_t digital_input_states() const;

    /// The drive's clock in seconds: control_time_.
    double seconds() const;
    void read_counts_per_turn();
    void read_units_and_polarity();
    void read_option_codes();
    void read_standstill_window();
    double rpm_to_counts(double rpm) const { return rpm * counts_per_turn_ / 60.0; }
    double counts_to_rpm(double counts) const { return counts * 60.0 / counts_per_turn_; }
    /// qc/s in velocity units (3.3: rpm × 10^0x608B).
    double counts_to_velocity(double counts) const {
        return counts_to_rpm(counts) / rpm_per_velocity_unit_;
    }
    // The plant's motor turns CCW for a positive value; the firmware's values are the plant's
    // times the polarity of 0x2008 bit 8 (8.2.41; 8.2.44: the counter "multiplied by Polarity").
    std::int64_t encoder_counter() const {
        return static_cast<std::int64_t>(polarity_) * axis_.position_actual();
    }
    double velocity_actual() const { return polarity_ * axis_.velocity_actual(); }
    double current_actual() const { return polarity_ * axis_.current_actual(); }
    std::int64_t position_actual() const { return encoder_counter() + position_offset_; }

    core::EventLoop& loop_;
    Epos2Dictionary dictionary_;
    canopen::Node node_;
    plant::AxisParameters machine_; ///< what the dictionary does not configure (see configure_axis)
    plant::ServoAxis axis_;
    motion::DeviceControl device_control_;
    motion::HomingProcedure homing_;
    motion::FollowingErrorMonitor following_error_;
    motion::SoftwarePositionLimitMonitor position_limit_;
    motion::StandstillMonitor standstill_;
    motion::I2tCurrentLimit i2t_;                   ///< 5.14.1, statusword bit 11
    PowerStageTemperature power_stage_temperature_; ///< 4.2.7
    motion::SystemLoad system_load_;                ///< set from outside (4.2.32)
    std::unique_ptr<ModeServices> mode_services_;
    std::unique_ptr<ModeBehaviour> mode_behaviour_;   ///< of mode_ (modes/)
    std::unique_ptr<Epos2Io> io_;                     ///< digital I/O, marker, compare, brake
    motion::SensorSupervision sensor_supervision_;    ///< 4.2.23 - 4.2.31
    motion::SensorDirectionMonitor sensor_direction_; ///< 4.2.37, 0x2008 bit 0 clear
    bool software_supervision_ = true;                ///< 0x2008 bit 0 clear (8.2.41)
    plant::SensorFaults sensor_faults_;               ///< injected
    bool winding_shorted_ = false;                    ///< injected (4.2.4)
    /// An error with "position reset" (table 4-11) was raised: its clearing resets the position.
    bool position_reset_on_clear_ = false;
    /// 0x81FE / 0x81FF: a queue of the CAN controller lost a frame, raised at the next period.
    std::optional<std::uint16_t> queue_overflow_;

    OperatingMode mode_ = OperatingMode::ProfilePosition;
    std::uint16_t controlword_ = 0;
    bool power_stage_on_ = false;
    bool stopping_ = false;           ///< a stop ramp of the device control has begun
    double hold_position_ = 0;        ///< where the power stage came on (Measure Init holds it)
    motion::MotionState last_demand_; ///< of the last control period
    motion::Trajectory stop_;         ///< the stop ramp in progress
    double stop_start_ = 0;
    std::int64_t position_offset_ = 0;          ///< what homing added to the axis' counter
    std::optional<std::int64_t> index_latch_;   ///< an index pulse since the last control period
    double counts_per_turn_ = 0;                ///< 4 × 0x2210 sub 1
    double rpm_per_velocity_unit_ = 1;          ///< 10^0x608B (3.3)
    int polarity_ = 1;                          ///< 0x2008 bit 8: 1 normal, -1 inverse
    std::int32_t digital_position_counter_ = 0; ///< of inputs 2 and 3 (5.7, 5.8), wrapping
    std::int64_t counter_at_index_ = 0;         ///< 0x2021: the raw encoder counter
    /// 8.2.47: the current filtered at 50 Hz every 0.1 ms; 8.2.48: the velocity at 5 Hz every ms.
    plant::LowPassFilter current_averaged_{50, plant::ServoAxis::kCurrentLoopPeriod};
    plant::LowPassFilter velocity_averaged_{5, plant::ServoAxis::kOuterLoopPeriod};

    /// The computed objects as last stored (none yet after a reset).
    struct PublishedValues {
        std::uint16_t statusword;
        std::int32_t position_demand;
        std::int32_t position_actual;
        std::int32_t velocity_demand;
        std::int32_t velocity_actual;
        std::int16_t current_actual;
        std::uint16_t digital_inputs;
    };
    std::optional<PublishedValues> published_;
    /// Where publish() stores them (0x6041, 0x6062, 0x6064, 0x606B, 0x606C, 0x6078, 0x2071 sub 1),
    /// looked up once.
    struct PublishedEntries {
        canopen::ValueRef statusword, position_demand, position_actual, velocity_demand,
            velocity_actual, current_actual, digital_inputs;
    };
    PublishedEntries published_entries_;
    /// The drive's clock: the scheduled time of the control period running, else of the next
    /// one, where an input written between two periods takes effect. Physics and profiles run
    /// on it alone, so a loop that runs late (real-time pace on a loaded host) gives the same
    /// samples as one on time.
    core::TimePoint control_time_;
    std::deque<std::uint16_t> pending_controlwords_; ///< written, not yet handled
    core::ScopedTimer controlword_timer_;
    core::ScopedTimer control_timer_;
};

} // namespace eposp::drives::epos2
