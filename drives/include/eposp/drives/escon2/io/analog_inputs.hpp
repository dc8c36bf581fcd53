#pragma once

#include "eposp/drives/escon2/io/digital_inputs.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace eposp::drives::escon2 {

/// ESCON2 FW spec table 68: the functionalities of an analog input (0x3161).
enum class AnalogInputFunction : std::uint8_t {
    GeneralPurposeA = 0,
    GeneralPurposeB = 1,
    CurrentSetValue = 8,
    VelocitySetValue = 9,
    CurrentSetValueOffset = 10,
    VelocitySetValueOffset = 11,
    None = 255,
};

/// The functionality of a 0x3161 value, or none for a reserved code.
std::optional<AnalogInputFunction> analog_input_function_from_code(std::uint8_t code);

inline constexpr unsigned kAnalogInputCount = 2;

/// 6.2.39: offset (0x3163 sub 1 / 3, mV there) applied before the gain (sub 2 / 4, 1/10'000).
struct AnalogInputAdjustment {
    double offset = 0; ///< V
    double gain = 1;
};

/// 0x3161 sub 1 / 2 (defaults table 67) and 0x3163.
struct AnalogInputConfiguration {
    std::array<AnalogInputFunction, kAnalogInputCount> functions{
        AnalogInputFunction::GeneralPurposeA, AnalogInputFunction::GeneralPurposeB};
    std::array<AnalogInputAdjustment, kAnalogInputCount> adjustments{};
};

/// Why the analog functions break table 68's rules (each function mapped once) or footnote [a]
/// / table 59 [e] with the digital inputs' ("for every target to control, only one input
/// functionality (analog or digital) can be active"), or nothing.
std::optional<std::string> configuration_error(const AnalogInputConfiguration& analog,
                                               const DigitalInputConfiguration& digital);

/// The two analog inputs (4.3, 6.2.36 - 6.2.40). The manual gives no ADC resolution ("consult
/// the hardware reference"): the raw value takes 12 bits over the variant's input range. Its
/// 10 kHz low-pass (4.3.1, a 16 µs time constant) is below any step the simulation takes and
/// is left out.
class AnalogInputs {
public:
    /// `low` / `high`: the variant's input range in V (tables 73, 76: ±10 V, Nano 0 - 5 V).
    AnalogInputs(double low = -10, double high = 10);

    /// The new configuration, or why it is refused (the old one stays); `digital` is the
    /// digital inputs' configuration the set value functions must not collide with.
    std::optional<std::string> configure(const AnalogInputConfiguration& config,
                                         const DigitalInputConfiguration& digital);
    const AnalogInputConfiguration& configuration() const { return config_; }

    /// The voltage at pin `input` (1 or 2), limited to the input range.
    void set_voltage(unsigned input, double volts);

    /// 0x3160 sub `input`: the adjusted voltage, (pin + offset) · gain, V.
    double voltage(unsigned input) const;
    /// 0x3164 sub `input`: the pin's ADC counts.
    std::uint16_t raw_value(unsigned input) const;
    /// 0x3162 sub 1 / 2: the adjusted voltage of the input configured as general purpose A / B,
    /// 0 if none is.
    double general_purpose(AnalogInputFunction which) const;
    /// The adjusted voltage the set value function `function` scales (6.2.48 - 6.2.51), if an
    /// input carries it.
    std::optional<double> voltage_for(AnalogInputFunction function) const;

    static constexpr unsigned kAdcBits = 12;

private:
    unsigned checked(unsigned input) const;

    double low_;
    double high_;
    AnalogInputConfiguration config_;
    std::array<double, kAnalogInputCount> pins_{};
};

} // namespace eposp::drives::escon2
