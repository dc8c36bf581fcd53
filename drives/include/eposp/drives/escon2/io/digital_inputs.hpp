#pragma once

#include "eposp/drives/escon2/io/debounced_input.hpp"
#include "eposp/drives/escon2/io/input_function.hpp"
#include "eposp/drives/escon2/protection/device_error_code.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace eposp::drives::escon2 {

/// Table 58: digital inputs 1 - 4 (bits 0 - 3) and high-speed digital inputs 1 - 4 (bits 4 - 7);
/// inputs are numbered 1 - 8 in that order, as the sub-indices of 0x3142.
inline constexpr unsigned kDigitalInputCount = 8;
inline constexpr unsigned kFirstHighSpeedInput = 5;

/// 0x3142 sub 1 - 8 and 0x3141 sub 2 with their defaults (6.2.26.2, 6.2.27).
struct DigitalInputConfiguration {
    std::array<InputFunction, kDigitalInputCount> functions{InputFunction::GeneralPurposeA,
                                                            InputFunction::GeneralPurposeB,
                                                            InputFunction::GeneralPurposeC,
                                                            InputFunction::GeneralPurposeD,
                                                            InputFunction::None,
                                                            InputFunction::None,
                                                            InputFunction::None,
                                                            InputFunction::None};
    std::uint16_t polarity = 0; ///< bit n-1 set: input n is active low
    /// 6.2.27: with sensor 2 configured (0x3000 sub 1) the high-speed inputs are disabled.
    bool sensor2_configured = false;
};

/// Why `config` breaks table 59's rules ("each function can only be mapped once", the PWM
/// functionalities only on digital input 1 or 2 [a]), or nothing.
std::optional<std::string> configuration_error(const DigitalInputConfiguration& config);

/// Tables 61 / 62: which fixed set values the set value switches select.
enum class SetValueSwitch { Velocity, Current };

/// The eight digital inputs of an ESCON2 (4.1, 6.2.26 - 6.2.28, 6.2.77): each pin filtered
/// (1 ms regular, 500 µs high-speed, 4.1.1), corrected by its polarity and read as the
/// functionality 0x3142 assigns it. Pins are driven from outside (a test, a wiring to another
/// device's output); every reading takes the virtual time `now` in seconds.
class DigitalInputs {
public:
    DigitalInputs();

    /// The new configuration, or why it is refused (the old one stays).
    std::optional<std::string> configure(const DigitalInputConfiguration& config);
    const DigitalInputConfiguration& configuration() const { return config_; }

    /// Pin `input` (1 - 8) driven high or low from `now` on.
    void set_level(unsigned input, bool high, double now);

    /// 0x3141 sub 1: the filtered pin levels before the polarity; 0 for a pin carrying a PWM
    /// functionality and for the high-speed pins while sensor 2 is configured.
    std::uint16_t logic_state(double now);
    /// 0x3143: the functionality states after the polarity (table 60).
    std::uint32_t functionality(double now);
    /// 0x60FD: the CiA functionalities of 0x3143 (limit switches, general purpose A - H).
    std::uint32_t cia_inputs(double now);
    /// Whether `function` is carried by an input and active.
    bool active(InputFunction function, double now);
    /// The input (1 - 8) carrying `function`, if any (a disabled high-speed input carries none).
    std::optional<unsigned> input_of(InputFunction function) const;

    /// Tables 61 / 62: the index (0 - 3) of Set velocity / current value 0 - 3 the two switches
    /// select, 2 · switch 1 + switch 0, an unmapped switch counting as 0; nothing if neither
    /// switch is mapped (then the set value comes from elsewhere).
    std::optional<unsigned> selected_set_value(SetValueSwitch which, double now);
    /// 7.1.28 / 7.1.29: the error an active limit switch raises (the negative one first).
    std::optional<DeviceErrorCode> limit_switch_error(double now);

private:
    bool enabled(unsigned index) const;

    DigitalInputConfiguration config_;
    std::array<DebouncedInput, kDigitalInputCount> pins_;
};

/// Table 59 [d], with Direction mapped: a negative set value is limited to zero, a positive one
/// kept while Direction is active and inverted while it is inactive. Without Direction mapped
/// (`direction` empty) the set value is unchanged.
double apply_direction(double set_value, std::optional<bool> direction);

} // namespace eposp::drives::escon2
