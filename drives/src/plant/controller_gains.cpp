#include "eposp/drives/plant/controller_gains.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eposp::drives::plant {

namespace {

constexpr double kMilli = 1e-3;
constexpr double kDeciMilli = 1e-4;
constexpr double kMicro = 1e-6;

template <typename Integer>
Integer in_units(double si, double unit) {
    const double value = std::round(si / unit);
    return static_cast<Integer>(std::clamp(value, double{std::numeric_limits<Integer>::min()},
                                           double{std::numeric_limits<Integer>::max()}));
}

} // namespace

CurrentGains to_si(const CurrentControlParameterSet& set) {
    // mV/(A·ms) is V/(A·s).
    return {set.p_gain * kMilli, static_cast<double>(set.i_gain)};
}

VelocityGains to_si(const VelocityControlParameterSet& set) {
    return {set.p_gain * kDeciMilli, set.i_gain * kMilli, set.velocity_feed_forward * kDeciMilli,
            set.acceleration_feed_forward * kMicro};
}

PositionGains to_si(const PositionControlParameterSet& set) {
    return {set.p_gain * kMilli, set.i_gain * kMilli, set.d_gain * kDeciMilli,
            set.velocity_feed_forward * kDeciMilli, set.acceleration_feed_forward * kMicro};
}

CurrentControlParameterSet to_parameter_set(const CurrentGains& gains) {
    return {in_units<std::int16_t>(gains.kp, kMilli), in_units<std::int16_t>(gains.ki, 1.0)};
}

VelocityControlParameterSet to_parameter_set(const VelocityGains& gains) {
    return {in_units<std::int16_t>(gains.kp, kDeciMilli), in_units<std::int16_t>(gains.ki, kMilli),
            in_units<std::uint16_t>(gains.velocity_feed_forward, kDeciMilli),
            in_units<std::uint16_t>(gains.acceleration_feed_forward, kMicro)};
}

PositionControlParameterSet to_parameter_set(const PositionGains& gains) {
    return {in_units<std::int16_t>(gains.kp, kMilli), in_units<std::int16_t>(gains.ki, kMilli),
            in_units<std::int16_t>(gains.kd, kDeciMilli),
            in_units<std::uint16_t>(gains.velocity_feed_forward, kDeciMilli),
            in_units<std::uint16_t>(gains.acceleration_feed_forward, kMicro)};
}

} // namespace eposp::drives::plant
