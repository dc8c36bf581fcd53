#include "eposp/drives/escon2/io/digital_outputs.hpp"

#include <cmath>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

constexpr std::uint32_t kGeneralPurposeBits = 0x0007'0000; ///< table 66, bits 16 - 18
constexpr unsigned kHighSpeedOutput = 2;                   ///< index of HsDigOut1
constexpr unsigned kCommutationsPerElectricalTurn = 6;

bool is_frequency_function(OutputFunction function) {
    return function == OutputFunction::HallSensorCommutationFrequency ||
           function == OutputFunction::HallSensorRotationFrequency;
}

std::uint32_t bit_of(OutputFunction function) {
    const auto code = static_cast<unsigned>(function);
    return code < 32 ? 1U << code : 0;
}

double fraction(double phase) {
    return phase - std::floor(phase);
}

} // namespace

std::optional<OutputFunction> output_function_from_code(std::uint8_t code) {
    if ((code >= 16 && code <= 18) || code == 25 || code == 26 || code == 32 || code == 33 ||
        code == 255) {
        return static_cast<OutputFunction>(code);
    }
    return std::nullopt;
}

std::optional<std::string> configuration_error(const DigitalOutputConfiguration& config) {
    unsigned frequency_outputs = 0;
    for (unsigned n = 0; n < kDigitalOutputCount; ++n) {
        const OutputFunction function = config.functions[n];
        if (function == OutputFunction::None) {
            continue;
        }
        if (is_frequency_function(function)) {
            if (n == kHighSpeedOutput) {
                return "a hall sensor frequency output cannot be mapped to the high-speed "
                       "digital output";
            }
            if (!config.hall_sensor_present) {
                return "a hall sensor frequency output needs a hall sensor (0x3000)";
            }
            if (++frequency_outputs > 1) {
                return "only one frequency output functionality can be used at a time";
            }
        }
        for (unsigned other = n + 1; other < kDigitalOutputCount; ++other) {
            if (config.functions[other] == function) {
                return "output functionality " + std::to_string(static_cast<unsigned>(function)) +
                       " is mapped to output " + std::to_string(n + 1) + " and output " +
                       std::to_string(other + 1) + "; a functionality can only be mapped once";
            }
        }
    }
    return std::nullopt;
}

std::optional<std::string> DigitalOutputs::configure(const DigitalOutputConfiguration& config) {
    if (std::optional<std::string> error = configuration_error(config)) {
        return error;
    }
    config_ = config;
    return std::nullopt;
}

void DigitalOutputs::write_general_purpose(std::uint32_t value) {
    general_purpose_ = value & kGeneralPurposeBits;
}

void DigitalOutputs::set_device_state(bool fault, bool limiting) {
    fault_ = fault;
    limiting_ = limiting;
}

void DigitalOutputs::step(double velocity_rpm, unsigned pole_pairs, double dt) {
    rotation_frequency_ = std::abs(velocity_rpm) / 60;
    pole_pairs_ = pole_pairs;
    rotation_phase_ = fraction(rotation_phase_ + rotation_frequency_ * dt);
    commutation_phase_ = fraction(commutation_phase_ +
                                  frequency(OutputFunction::HallSensorCommutationFrequency) * dt);
}

double DigitalOutputs::frequency(OutputFunction function) const {
    switch (function) {
    case OutputFunction::HallSensorRotationFrequency:
        return rotation_frequency_;
    case OutputFunction::HallSensorCommutationFrequency:
        return rotation_frequency_ * pole_pairs_ * kCommutationsPerElectricalTurn;
    default:
        return 0;
    }
}

// Table 66: ready/fault "inactive on device fault or fault reaction state, otherwise active",
// limitation "active if an internal limit (Statusword Bit 11) is active".
std::uint32_t DigitalOutputs::functionality() const {
    std::uint32_t states = general_purpose_;
    if (!fault_) {
        states |= bit_of(OutputFunction::ReadyFault);
    }
    if (limiting_) {
        states |= bit_of(OutputFunction::Limitation);
    }
    return states;
}

std::uint32_t DigitalOutputs::cia_outputs() const {
    return general_purpose_;
}

// 6.2.33.2: polarity 1 inverts; "not configured pins will remain zero"; no polarity on a
// frequency output.
std::uint16_t DigitalOutputs::logic_state() const {
    const std::uint32_t states = functionality();
    std::uint16_t pins = 0;
    for (unsigned n = 0; n < kDigitalOutputCount; ++n) {
        const OutputFunction function = config_.functions[n];
        const bool disabled = config_.sensor2_configured && n == kHighSpeedOutput;
        if (function == OutputFunction::None || is_frequency_function(function) || disabled) {
            continue;
        }
        const bool active = (states & bit_of(function)) != 0;
        const bool inverted = (config_.polarity & (1U << n)) != 0;
        if (active != inverted) {
            pins = static_cast<std::uint16_t>(pins | (1U << n));
        }
    }
    return pins;
}

bool DigitalOutputs::pin(unsigned output) const {
    if (output < 1 || output > kDigitalOutputCount) {
        throw std::out_of_range("ESCON2 digital output " + std::to_string(output) +
                                " does not exist (1, 2, 3 = high-speed 1)");
    }
    const OutputFunction function = config_.functions[output - 1];
    if (function == OutputFunction::HallSensorRotationFrequency) {
        return rotation_phase_ < 0.5;
    }
    if (function == OutputFunction::HallSensorCommutationFrequency) {
        return commutation_phase_ < 0.5;
    }
    return (logic_state() & (1U << (output - 1))) != 0;
}

} // namespace eposp::drives::escon2
