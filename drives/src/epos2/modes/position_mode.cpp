#include "position_mode.hpp"

#include "analog_setpoint.hpp"

namespace eposp::drives::epos2 {

void PositionMode::start(double, std::int64_t position, bool) {
    limiter_ = motion::PositionSetValueLimiter(static_cast<double>(position));
}

// Table 5-38 / 5.6: the setting value, or the analog set value when executed.
double PositionMode::set_value() const {
    const auto& od = services_.objects;
    return executed_analog_setpoint(od, AnalogSetpoint::Position)
        .value_or(static_cast<double>(od.get_as<std::int32_t>(0x2062, 0)));
}

ModeDemand PositionMode::demand(const ModeInputs&) {
    return {.motion = services_.follow_position_set_value(limiter_, set_value())};
}

} // namespace eposp::drives::epos2
