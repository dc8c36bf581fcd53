#include "position_mode.hpp"

#include "analog_setpoint.hpp"

#include <algorithm>

namespace eposp::drives::epos2 {

void PositionMode::start(double, std::int64_t position, bool) {
    limiter_ = motion::PositionSetValueLimiter(static_cast<double>(position));
}

// Table 5-38 / 5.6: the setting value, or the analog set value when executed; 0x607D limits it.
double PositionMode::set_value() const {
    const auto& od = services_.objects;
    const double written = executed_analog_setpoint(od, AnalogSetpoint::Position)
                               .value_or(static_cast<double>(od.get_as<std::int32_t>(0x2062, 0)));
    return std::clamp(written, static_cast<double>(od.get_as<std::int32_t>(0x607D, 1)),
                      static_cast<double>(od.get_as<std::int32_t>(0x607D, 2)));
}

ModeDemand PositionMode::demand(const ModeInputs&) {
    const auto& od = services_.objects;
    return {.motion = limiter_.update(set_value(),
                                      services_.rpm_to_counts(od.get_as<std::uint32_t>(0x607F, 0)),
                                      services_.rpm_to_counts(od.get_as<std::uint32_t>(0x60C5, 0)),
                                      plant::ServoAxis::kOuterLoopPeriod)};
}

} // namespace eposp::drives::epos2
