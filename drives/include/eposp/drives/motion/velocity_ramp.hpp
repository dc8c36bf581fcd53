#pragma once

namespace eposp::drives::motion {

/// Motion Profile Type 0x6086 (EPOS2 FW spec 5.3.2.2).
enum class RampShape {
    Linear,     ///< 0: constant acceleration, trapezoidal velocity (figure 5-8)
    SinSquared, ///< 1: acceleration a(t) = A·sin²(π·t/T), jerk-limited (figure 5-9)
};

/// Position, velocity and acceleration at one instant, in consistent units (e.g. quadcounts,
/// quadcounts/s, quadcounts/s²).
struct MotionState {
    double position = 0;
    double velocity = 0;
    double acceleration = 0;
};

/// One piece of a profile: the velocity changes from v_start to v_end over `duration` with the
/// given shape (a cruise when both are equal).
struct RampSegment {
    double duration = 0;
    double v_start = 0;
    double v_end = 0;
    RampShape shape = RampShape::Linear;
};

/// k in "a ramp lasts k·|Δv|/A and covers k·(v1² − v0²)/(2A)": 1 linear, 2 sin².
double ramp_time_factor(RampShape shape);

/// Figures 5-8/5-9 name the profile acceleration Amax for both shapes, so it is the peak
/// acceleration: a linear ramp takes |Δv|/A, a sin² ramp (mean acceleration A/2) twice as long.
double ramp_duration(double delta_v, double peak_acceleration, RampShape shape);

/// Both shapes are point-symmetric in velocity, so a ramp covers (v_start + v_end)/2 · duration.
double ramp_distance(double v_start, double v_end, double peak_acceleration, RampShape shape);

/// A ramp from v_start to v_end at the given peak acceleration.
RampSegment make_ramp(double v_start, double v_end, double peak_acceleration, RampShape shape);

/// The distance a segment covers: (v_start + v_end)/2 · duration.
double distance_covered(const RampSegment& segment);

/// The displacement from the segment's start, velocity and acceleration at time t in [0, duration]
/// (closed forms).
MotionState sample_segment(const RampSegment& segment, double t);

} // namespace eposp::drives::motion
