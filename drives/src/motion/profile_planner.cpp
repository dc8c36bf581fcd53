#include "eposp/drives/motion/profile_planner.hpp"

#include <algorithm>
#include <cmath>

namespace eposp::drives::motion {

namespace {

double sign(double value) {
    return value < 0 ? -1.0 : 1.0;
}

// From rest or moving towards the target with room to stop: accelerate to the peak velocity,
// cruise, decelerate. Works in the frame where the target lies ahead (distance ≥ 0).
std::vector<RampSegment> forward_move(double v0, double distance, const ProfileParameters& p) {
    const double k = ramp_time_factor(p.shape);
    const double a = p.acceleration;
    const double d = p.deceleration;
    // Triangular when the distance is too short for the profile velocity:
    // k(vp² − v0²)/(2a) + k·vp²/(2d) = distance. A max velocity lowered while moving (v0 above
    // it) slows down to it first.
    const double reachable =
        std::sqrt(std::max((2 * distance * a * d / k + v0 * v0 * d) / (a + d), v0 * v0));
    const RampSegment first = v0 > p.velocity
                                  ? make_ramp(v0, p.velocity, d, p.shape)
                                  : make_ramp(v0, std::min(reachable, p.velocity), a, p.shape);
    const double peak = first.v_end;
    const RampSegment stop = make_ramp(peak, 0, d, p.shape);
    if (peak <= 0) {
        return {};
    }
    const double cruise = distance - distance_covered(first) - distance_covered(stop);
    return {first, {cruise / peak, peak, peak, p.shape}, stop};
}

std::vector<RampSegment> mirrored(std::vector<RampSegment> segments, double direction) {
    for (RampSegment& segment : segments) {
        segment.v_start *= direction;
        segment.v_end *= direction;
    }
    return segments;
}

} // namespace

core::Result<ProfileParameters> clamp_to_limits(const ProfileParameters& parameters,
                                                const ProfileLimits& limits) {
    if (parameters.velocity <= 0 || parameters.acceleration <= 0 || parameters.deceleration <= 0) {
        return core::Error{"profile velocity, acceleration and deceleration must be positive"};
    }
    if (limits.max_velocity <= 0 || limits.max_acceleration <= 0) {
        return core::Error{"max profile velocity and max acceleration must be positive"};
    }
    ProfileParameters clamped = parameters;
    clamped.velocity = std::min(parameters.velocity, limits.max_velocity);
    clamped.acceleration = std::min(parameters.acceleration, limits.max_acceleration);
    clamped.deceleration = std::min(parameters.deceleration, limits.max_acceleration);
    return clamped;
}

Trajectory plan_position_move(const MotionState& start, double target,
                              const ProfileParameters& parameters) {
    const double v0 = start.velocity;
    const double stopping_point =
        start.position +
        sign(v0) * ramp_distance(std::abs(v0), 0, parameters.deceleration, parameters.shape);
    const bool overshoots = v0 != 0 && (target - stopping_point) * v0 < 0;
    if (overshoots) {
        std::vector<RampSegment> segments{
            make_ramp(v0, 0, parameters.deceleration, parameters.shape)};
        const Trajectory back = plan_position_move({stopping_point, 0, 0}, target, parameters);
        segments.insert(segments.end(), back.segments().begin(), back.segments().end());
        return {start.position, std::move(segments)};
    }
    const double distance = target - start.position;
    const double direction = distance != 0 ? sign(distance) : sign(v0);
    if (distance == 0 && v0 == 0) {
        return {start.position, {}};
    }
    return {start.position,
            mirrored(forward_move(v0 * direction, std::abs(distance), parameters), direction)};
}

Trajectory plan_velocity_change(const MotionState& start, double target_velocity,
                                const ProfileParameters& parameters) {
    const double v0 = start.velocity;
    const RampShape shape = parameters.shape;
    std::vector<RampSegment> segments;
    if (v0 != 0 && v0 * target_velocity < 0) {
        segments.push_back(make_ramp(v0, 0, parameters.deceleration, shape));
        segments.push_back(make_ramp(0, target_velocity, parameters.acceleration, shape));
    } else {
        const bool speeding_up = std::abs(target_velocity) > std::abs(v0);
        segments.push_back(
            make_ramp(v0, target_velocity,
                      speeding_up ? parameters.acceleration : parameters.deceleration, shape));
    }
    return {start.position, std::move(segments)};
}

Trajectory plan_stop(const MotionState& start, double deceleration, RampShape shape) {
    return {start.position, {make_ramp(start.velocity, 0, deceleration, shape)}};
}

} // namespace eposp::drives::motion
