#include "eposp/drives/epos2/digital_inputs.hpp"

#include <stdexcept>
#include <string>

namespace eposp::drives::epos2 {
void DigitalInputs::set_level(unsigned input, bool high) {
    if (input < 1 || input > kDigitalInputCount) {
        throw std::invalid_argument("EPOS2 24/5 digital input " + std::to_string(input) +
                                    " does not exist (1 … 6)");
    }
    const auto pin = static_cast<std::uint8_t>(1U << (input - 1));
    outside_ = static_cast<std::uint8_t>(high ? outside_ | pin : outside_ & ~pin);
}

void DigitalInputs::hold_limit_switch(InputFunction which, bool pressed) {
    (which == InputFunction::NegativeLimitSwitch ? held_.negative_limit : held_.positive_limit) =
        pressed;
}

// 8.2.57, table 8-88: polarity 0 is high active, 1 low active. A functionality no input carries
// stays inactive whatever its polarity.
void DigitalInputs::configure(const DigitalInputConfiguration& config) {
    config_ = config;
    for (unsigned pins = 0; pins < states_by_levels_.size(); ++pins) {
        std::uint16_t states = 0;
        for (unsigned n = 0; n < kDigitalInputCount; ++n) {
            const std::uint16_t function = config_.functions[n];
            if (function > 15) {
                continue; // refused by the value range; kept out for safety
            }
            const auto bit = static_cast<std::uint16_t>(1U << function);
            const bool high = (pins & (1U << n)) != 0;
            const bool low_active = (config_.polarity & bit) != 0;
            if (high != low_active) {
                states |= bit;
            }
        }
        states_by_levels_[pins] = states;
    }
}

} // namespace eposp::drives::epos2
