#include "eposp/drives/motion/trajectory.hpp"

#include <algorithm>

namespace eposp::drives::motion {

Trajectory::Trajectory(double start_position, std::vector<RampSegment> segments)
    : start_position_(start_position), final_position_(start_position) {
    // Rounding can leave a cruise of -1e-17 s; empty pieces carry no motion.
    std::erase_if(segments, [](const RampSegment& s) { return s.duration <= 0; });
    segments_ = std::move(segments);
    segment_starts_.reserve(segments_.size());
    for (const RampSegment& segment : segments_) {
        segment_starts_.push_back(final_position_);
        duration_ += segment.duration;
        final_position_ += sample_segment(segment, segment.duration).position;
    }
}

double Trajectory::final_velocity() const {
    return segments_.empty() ? 0.0 : segments_.back().v_end;
}

MotionState Trajectory::sample(double t) const {
    double remaining = std::max(t, 0.0);
    for (std::size_t i = 0; i < segments_.size(); ++i) {
        const RampSegment& segment = segments_[i];
        if (remaining <= segment.duration) {
            MotionState state = sample_segment(segment, remaining);
            state.position += segment_starts_[i];
            return state;
        }
        remaining -= segment.duration;
    }
    const double velocity = final_velocity();
    return {final_position_ + velocity * remaining, velocity, 0};
}

} // namespace eposp::drives::motion
