#pragma once

#include "eposp/drives/motion/velocity_ramp.hpp"

namespace eposp::drives::motion {

/// One piece of a PVT motion (EPOS2 FW spec 5.5.1): the cubic from position p0 at velocity v0 to
/// p1 at v1 in `duration` seconds, P(t) = a t³ + b t² + c t + d with the spec's coefficients.
class PvtSegment {
public:
    PvtSegment(double p0, double v0, double p1, double v1, double duration);

    /// The state t seconds after the start, 0 <= t <= duration.
    MotionState at(double t) const;
    double duration() const { return duration_; }

private:
    double a_;
    double b_;
    double c_;
    double d_;
    double duration_;
};

} // namespace eposp::drives::motion
