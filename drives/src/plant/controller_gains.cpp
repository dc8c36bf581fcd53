#include "eposp/drives/plant/controller_gains.hpp"

namespace eposp::drives::plant {

namespace {

constexpr double kMilli = 1e-3;
constexpr double kDeciMilli = 1e-4;
constexpr double kMicro = 1e-6;

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

} // namespace eposp::drives::plant
