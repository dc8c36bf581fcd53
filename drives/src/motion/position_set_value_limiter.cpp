#include "eposp/drives/motion/position_set_value_limiter.hpp"

#include <algorithm>
#include <cmath>

namespace eposp::drives::motion {
namespace {

// The speed from which steps of `dt`, each `acceleration`·dt slower, stop within `distance`:
// n steps from v = n·a·dt cover a·dt²·n(n+1)/2.
double braking_speed(double distance, double acceleration, double dt) {
    const double step = acceleration * dt;
    const double n = std::sqrt(0.25 + 2 * distance / (step * dt)) - 0.5;
    return n * step;
}

} // namespace

PositionSetValueLimiter::PositionSetValueLimiter(double position)
    : demand_{position, 0, 0}, last_set_value_(position) {}

MotionState PositionSetValueLimiter::update(double set_value, double max_velocity,
                                            double max_acceleration, double dt) {
    const double set_velocity =
        std::clamp((set_value - last_set_value_) / dt, -max_velocity, max_velocity);
    last_set_value_ = set_value;
    // The distance left once the demand has moved along with the set value for this period.
    const double behind = set_value - (demand_.position + set_velocity * dt);
    const double catch_up =
        std::copysign(braking_speed(std::abs(behind), max_acceleration, dt), behind);
    const double wanted = std::clamp(set_velocity + catch_up, -max_velocity, max_velocity);
    const double step = max_acceleration * dt;
    double velocity = std::clamp(wanted, demand_.velocity - step, demand_.velocity + step);
    double position = demand_.position + velocity * dt;
    // Reaching (closer than the rounding of the braking curve) or crossing the set value when
    // the velocity that lands on it is within one step: on it (a set value moving within the
    // limits lands at its own velocity).
    constexpr double kReached = 1e-3; // quadcounts
    const bool crossed = (set_value - position) * (set_value - demand_.position) <= 0 ||
                         std::abs(set_value - position) < kReached;
    const double landing = (set_value - demand_.position) / dt;
    if (crossed && std::abs(landing - demand_.velocity) <= step) {
        position = set_value;
        velocity = landing;
    }
    demand_ = {position, velocity, (velocity - demand_.velocity) / dt};
    return demand_;
}

} // namespace eposp::drives::motion
