#include "eposp/drives/motion/velocity_ramp.hpp"

#include <cmath>
#include <numbers>

namespace eposp::drives::motion {

double ramp_time_factor(RampShape shape) {
    return shape == RampShape::SinSquared ? 2.0 : 1.0;
}

double ramp_duration(double delta_v, double peak_acceleration, RampShape shape) {
    return ramp_time_factor(shape) * std::abs(delta_v) / peak_acceleration;
}

double ramp_distance(double v_start, double v_end, double peak_acceleration, RampShape shape) {
    return distance_covered(make_ramp(v_start, v_end, peak_acceleration, shape));
}

RampSegment make_ramp(double v_start, double v_end, double peak_acceleration, RampShape shape) {
    return {ramp_duration(v_end - v_start, peak_acceleration, shape), v_start, v_end, shape};
}

double distance_covered(const RampSegment& segment) {
    return 0.5 * (segment.v_start + segment.v_end) * segment.duration;
}

MotionState sample_segment(const RampSegment& segment, double t) {
    const double v0 = segment.v_start;
    const double dv = segment.v_end - segment.v_start;
    const double duration = segment.duration;
    if (duration <= 0 || dv == 0) {
        return {v0 * t, v0, 0};
    }
    if (segment.shape == RampShape::Linear) {
        const double a = dv / duration;
        return {v0 * t + 0.5 * a * t * t, v0 + a * t, a};
    }
    // a(t) = (Δv/T)·(1 − cos 2πt/T); v and p are its integrals from 0.
    constexpr double kTwoPi = 2 * std::numbers::pi;
    const double phase = kTwoPi * t / duration;
    const double acceleration = dv / duration * (1 - std::cos(phase));
    const double velocity = v0 + dv * (t / duration - std::sin(phase) / kTwoPi);
    const double position = v0 * t + dv * (0.5 * t * t / duration -
                                           duration * (1 - std::cos(phase)) / (kTwoPi * kTwoPi));
    return {position, velocity, acceleration};
}

} // namespace eposp::drives::motion
