#include "eposp/drives/epos2/digital_outputs.hpp"

#include <algorithm>

namespace eposp::drives::epos2 {
namespace {

// Table 8-94: the configurations that name a functionality of table 8-92 (0 … 2, 11 … 15).
bool drives_pin(std::uint16_t function) {
    return function <= 2 || (function >= 11 && function <= 15);
}

} // namespace

bool DigitalOutputConfiguration::has(OutputFunction function) const {
    return std::ranges::find(functions, static_cast<std::uint16_t>(function)) != functions.end();
}

void DigitalOutputs::update(std::uint16_t states) {
    if (applied_ == states) {
        return;
    }
    applied_ = states;
    for (unsigned n = 0; n < kDigitalOutputCount; ++n) {
        const std::uint16_t function = config_.functions[n];
        if (!drives_pin(function)) {
            continue;
        }
        const auto bit = static_cast<std::uint16_t>(1U << function);
        if ((config_.mask & bit) == 0) {
            continue;
        }
        const bool high = ((states ^ config_.polarity) & bit) != 0;
        const auto pin = static_cast<std::uint8_t>(1U << n);
        levels_ = static_cast<std::uint8_t>(high ? levels_ | pin : levels_ & ~pin);
    }
}

} // namespace eposp::drives::epos2
