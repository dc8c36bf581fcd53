#include "mode_behaviour.hpp"

#include <algorithm>

namespace eposp::drives::epos2 {

// 5.3.2.1 / 5.10.2.1: the profile clamped to Maximal Profile Velocity 0x607F and Max
// Acceleration 0x60C5 (all of them at least 1 by their value ranges, so the clamp cannot fail).
motion::ProfileParameters ModeServices::profile_parameters() const {
    const motion::ProfileParameters written{
        .velocity = velocity_to_counts(objects.get_as<std::uint32_t>(0x6081, 0)),
        .acceleration = rpm_to_counts(objects.get_as<std::uint32_t>(0x6083, 0)),
        .deceleration = rpm_to_counts(objects.get_as<std::uint32_t>(0x6084, 0)),
        .shape = static_cast<motion::RampShape>(objects.get_as<std::int16_t>(0x6086, 0))};
    const motion::ProfileLimits limits{
        .max_velocity = velocity_to_counts(objects.get_as<std::uint32_t>(0x607F, 0)),
        .max_acceleration = rpm_to_counts(objects.get_as<std::uint32_t>(0x60C5, 0))};
    return *motion::clamp_to_limits(written, limits);
}

motion::MotionState
ModeServices::follow_position_set_value(motion::PositionSetValueLimiter& limiter,
                                        double set_value) const {
    const double limited =
        std::clamp(set_value, static_cast<double>(objects.get_as<std::int32_t>(0x607D, 1)),
                   static_cast<double>(objects.get_as<std::int32_t>(0x607D, 2)));
    return limiter.update(limited, velocity_to_counts(objects.get_as<std::uint32_t>(0x607F, 0)),
                          rpm_to_counts(objects.get_as<std::uint32_t>(0x60C5, 0)),
                          plant::ServoAxis::kOuterLoopPeriod);
}

} // namespace eposp::drives::epos2
