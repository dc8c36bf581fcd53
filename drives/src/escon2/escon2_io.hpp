#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/drives/escon2/io/analog_inputs.hpp"
#include "eposp/drives/escon2/io/analog_outputs.hpp"
#include "eposp/drives/escon2/io/digital_inputs.hpp"
#include "eposp/drives/escon2/io/digital_outputs.hpp"
#include "eposp/drives/escon2/io/pwm_input.hpp"
#include "eposp/drives/escon2/protection/device_error_code.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace eposp::drives::escon2 {

/// The set values the inputs command in the present mode (3.3.1.2, 3.4.1.2), in the objects'
/// units (velocity units, mA); empty where no input carries the function (the host's value
/// stays).
struct InputSetValues {
    std::optional<std::int32_t> velocity;
    std::optional<std::int32_t> velocity_offset;
    std::optional<std::int32_t> current;
    std::optional<std::int32_t> current_offset;
};

/// What the inputs ask of the device control and the error handling in one control period.
struct IoReaction {
    InputSetValues set_values;
    std::optional<bool> drive_enable;        ///< the Drive enable functionality changed to this
    std::optional<bool> quick_stop;          ///< the Quick stop functionality changed to this
    std::vector<DeviceErrorCode> conditions; ///< limit switches, PWM warnings and errors
    std::vector<DeviceErrorCode> cleared;    ///< PWM warnings whose cause went away
};

/// The drive's state the outputs show.
struct IoState {
    double now = 0; ///< s
    bool velocity_mode = true;
    bool fault = false;    ///< Fault or Fault reaction active (ready/fault inactive)
    bool limiting = false; ///< statusword bit 11
    MonitoredValues monitored;
    double velocity_rpm = 0; ///< the motor shaft's, for the Hall frequency outputs
    unsigned pole_pairs = 1;
};

/// The ESCON2's inputs and outputs (chapter 4, 6.2.26 - 6.2.54, 6.2.77, 6.2.78) on the
/// dictionary: the standalone I/O classes (io/) configured from their objects whenever these
/// change, their pins driven from outside, and once per control period their display objects
/// stored, the set values they command scaled as 0x3146 / 0x3147 and 0x3180 - 0x31B5 say, and
/// the outputs set from the drive's state.
class Escon2Io {
public:
    Escon2Io(canopen::ObjectDictionary& od, double analog_input_low, double analog_input_high,
             double analog_output_low, double analog_output_high, double now);

    /// Re-reads every configuration object (after a power-up, which tells no listener).
    void reload();

    void set_digital_input(unsigned input, bool high, double now);
    bool digital_input(unsigned input) const;
    /// A steady PWM signal at digital input 1 or 2 (none: the pin's level alone).
    void set_pwm_signal(unsigned input, std::optional<PwmSignal> signal);
    void set_analog_input(unsigned input, double volts);
    bool digital_output(unsigned output) const { return digital_outputs_.pin(output); }
    double analog_output(unsigned output) const { return analog_outputs_.voltage(output); }

    /// The inputs at the end of the control period ending at `now`.
    IoReaction read_inputs(double period_start, double now, bool velocity_mode);
    /// The outputs after it.
    void write_outputs(const IoState& state, double dt);

private:
    void configure_digital_inputs();
    void configure_analog_inputs();
    void configure_digital_outputs();
    void configure_analog_outputs();
    void watch();
    std::optional<double> pwm_duty_cycle(InputFunction function) const;
    TwoPointScaling scaling(std::uint16_t index, double input_unit, double value_unit) const;
    std::optional<double> set_value(bool velocity, bool offset, double now);
    template <typename T>
    void store(std::uint16_t index, std::uint8_t sub, T value);

    canopen::ObjectDictionary& od_;
    DigitalInputs digital_inputs_;
    std::array<PwmInput, 2> pwm_inputs_;
    std::array<std::optional<PwmSignal>, 2> pwm_signals_;
    AnalogInputs analog_inputs_;
    DigitalOutputs digital_outputs_;
    AnalogOutputs analog_outputs_;
    bool drive_enable_ = false;
    bool quick_stop_ = false;
    bool storing_ = false; ///< the device stores 0x3152 / 0x60FE: not a host's write
};

} // namespace eposp::drives::escon2
