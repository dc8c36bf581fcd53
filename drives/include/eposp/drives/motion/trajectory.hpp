#pragma once

#include "eposp/drives/motion/velocity_ramp.hpp"

#include <vector>

namespace eposp::drives::motion {

/// A profile as a start position and a sequence of ramps; after the last ramp the final velocity
/// is held (zero for a positioning move, the target velocity for a velocity profile).
class Trajectory {
public:
    Trajectory() = default;
    Trajectory(double start_position, std::vector<RampSegment> segments);

    /// The state at time t after the start (t < 0 reads the start).
    MotionState sample(double t) const;
    double duration() const { return duration_; }
    double start_position() const { return start_position_; }
    double final_position() const { return final_position_; }
    double final_velocity() const;
    const std::vector<RampSegment>& segments() const { return segments_; }

private:
    double start_position_ = 0;
    std::vector<RampSegment> segments_;
    /// Where each segment starts, summed once in segment order as sample() summed them at every
    /// sample (the same additions, so the same bits): a drive samples every millisecond.
    std::vector<double> segment_starts_;
    double duration_ = 0;
    double final_position_ = 0;
};

} // namespace eposp::drives::motion
