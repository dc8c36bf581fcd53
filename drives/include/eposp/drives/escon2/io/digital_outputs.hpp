#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace eposp::drives::escon2 {

/// ESCON2 FW spec table 65: the functionalities of a digital output (0x3151); codes below 32
/// are also their bit in Digital outputs functionality 0x3152 (table 66).
enum class OutputFunction : std::uint8_t {
    GeneralPurposeA = 16,
    GeneralPurposeB = 17,
    GeneralPurposeC = 18,
    ReadyFault = 25,
    Limitation = 26,
    HallSensorCommutationFrequency = 32,
    HallSensorRotationFrequency = 33,
    None = 255,
};

/// The functionality of a 0x3151 value, or none for a reserved code.
std::optional<OutputFunction> output_function_from_code(std::uint8_t code);

/// Table 63: digital output 1 (bit 0), digital output 2 (bit 1), high-speed digital output 1
/// (bit 2); outputs are numbered 1 - 3 in that order, as the sub-indices of 0x3151.
inline constexpr unsigned kDigitalOutputCount = 3;

/// 0x3151 sub 1 - 3 (defaults table 64), 0x3150 sub 2, and what the sensors configuration
/// (0x3000) decides for the outputs.
struct DigitalOutputConfiguration {
    std::array<OutputFunction, kDigitalOutputCount> functions{
        OutputFunction::GeneralPurposeA, OutputFunction::GeneralPurposeB, OutputFunction::None};
    std::uint16_t polarity = 0;      ///< bit n-1 set: output n inverted
    bool hall_sensor_present = true; ///< the frequency outputs need one (table 65)
    bool sensor2_configured = false; ///< disables the high-speed output (6.2.34)
};

/// Why `config` breaks table 65 / 6.2.34 (a function mapped twice, both frequency outputs at
/// once, a frequency output on the high-speed output or without a hall sensor), or nothing.
std::optional<std::string> configuration_error(const DigitalOutputConfiguration& config);

/// The three digital outputs (4.2, 6.2.33 - 6.2.35, 6.2.78): the functionality states of
/// 0x3152 (general purpose A - C written by the host, ready/fault and limitation from the
/// device), each output's pin after its polarity, and the hall sensor frequency outputs as a
/// square wave whose phase follows the motor speed in virtual time.
class DigitalOutputs {
public:
    /// The new configuration, or why it is refused (the old one stays).
    std::optional<std::string> configure(const DigitalOutputConfiguration& config);
    const DigitalOutputConfiguration& configuration() const { return config_; }

    /// 0x3152 or 0x60FE sub 1 written: the general purpose bits 16 - 18 are taken, the others
    /// are the device's (24 - 31 "are ignored upon writing").
    void write_general_purpose(std::uint32_t value);
    /// The device's state: in Fault or Fault reaction active (ready/fault inactive), an internal
    /// limit active (statusword bit 11).
    void set_device_state(bool fault, bool limiting);
    /// The motor's speed (rpm) during the last `dt` s and its pole pairs: advances the frequency
    /// outputs.
    void step(double velocity_rpm, unsigned pole_pairs, double dt);

    /// 0x3152: the functionality states before the polarity.
    std::uint32_t functionality() const;
    /// 0x60FE sub 1: its general purpose bits.
    std::uint32_t cia_outputs() const;
    /// 0x3150 sub 1: the pins of outputs with a state functionality, after the polarity; 0 for
    /// unconfigured outputs and frequency outputs.
    std::uint16_t logic_state() const;
    /// The level at pin `output` (1 - 3), frequency outputs included: what a wired input sees.
    bool pin(unsigned output) const;
    /// The frequency (Hz) a frequency output carries: the rotation frequency is the shaft's
    /// turns per second, the commutation frequency one period per hall sensor state change, six
    /// per electrical turn (the manual gives no formula).
    double frequency(OutputFunction function) const;

private:
    DigitalOutputConfiguration config_;
    std::uint32_t general_purpose_ = 0;
    bool fault_ = false;
    bool limiting_ = false;
    double rotation_frequency_ = 0; ///< Hz
    unsigned pole_pairs_ = 1;
    double rotation_phase_ = 0;    ///< turns, fractional
    double commutation_phase_ = 0; ///< periods, fractional
};

} // namespace eposp::drives::escon2
