#include "eposp/drives/motion/trajectory.hpp"

#include <algorithm>

namespace eposp::drives::motion {

Trajectory::Trajectory(double start_position, std::vector<RampSegment> segments)
    : start_position_(start_position), final_position_(start_position) {
    // Rounding can leave a cruise of -1e-17 s; empty pieces carry no motion.
    std::erase_if(segments, [](const RampSegment& s) { return s.duration <= 0; });
    segments_ = std::move(segments);
    for (const RampSegment& segment : segments_) {
        duration_ += segment.duration;
        final_position_ += sample_segment(segment, segment.duration).position;
    }
}

double Trajectory::final_velocity() const {
    return segments_.empty() ? 0.0 : segments_.back().v_end;
}

MotionState Trajectory::sample(double t) const {
    double position = start_position_;
    double remaining = std::max(t, 0.0);
    for (const RampSegment& segment : segments_) {
        if (remaining <= segment.duration) {
            MotionState state = sample_segment(segment, remaining);
            state.position += position;
            return state;
        }
        position += sample_segment(segment, segment.duration).position;
        remaining -= segment.duration;
    }
    const double velocity = final_velocity();
    return {position + velocity * remaining, velocity, 0};
}

} // namespace eposp::drives::motion
