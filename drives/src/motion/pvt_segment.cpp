#include "eposp/drives/motion/pvt_segment.hpp"

namespace eposp::drives::motion {

PvtSegment::PvtSegment(double p0, double v0, double p1, double v1, double duration)
    : a_((-2 * (p1 - p0) + duration * (v1 + v0)) / (duration * duration * duration)),
      b_((3 * (p1 - p0) - duration * (v1 + 2 * v0)) / (duration * duration)), c_(v0), d_(p0),
      duration_(duration) {}

MotionState PvtSegment::at(double t) const {
    return {.position = ((a_ * t + b_) * t + c_) * t + d_,
            .velocity = (3 * a_ * t + 2 * b_) * t + c_,
            .acceleration = 6 * a_ * t + 2 * b_};
}

} // namespace eposp::drives::motion
