#include "digital_position_mode.hpp"

namespace eposp::drives::epos2 {

void DigitalPositionMode::start(double, std::int64_t position, bool) {
    limiter_ = motion::PositionSetValueLimiter(static_cast<double>(position));
    held_ = static_cast<double>(position);
}

void DigitalPositionMode::stop_completed(double position) {
    limiter_ = motion::PositionSetValueLimiter(position);
    held_ = position;
}

ModeDemand DigitalPositionMode::demand(const ModeInputs&) {
    const auto& od = services_.objects;
    const std::int32_t counter = services_.digital_position_counter;
    const std::int32_t desired = od.get_as<std::uint8_t>(0x2300, 4) == 0 ? counter : -counter;
    services_.outputs.set_as(0x2300, 1, desired);
    const auto denominator = od.get_as<std::uint16_t>(0x2300, 3);
    if (denominator != 0) {
        held_ = static_cast<double>(desired) * od.get_as<std::uint16_t>(0x2300, 2) / denominator +
                od.get_as<std::int32_t>(0x2300, 5);
    }
    return {.motion = services_.follow_position_set_value(limiter_, held_)};
}

} // namespace eposp::drives::epos2
