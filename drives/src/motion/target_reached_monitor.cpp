#include "eposp/drives/motion/target_reached_monitor.hpp"

#include <cmath>

namespace eposp::drives::motion {

TargetReachedMonitor::TargetReachedMonitor(TargetWindow window)
    : window_(window), timer_(window.time_ms * 1e-3) {}

bool TargetReachedMonitor::update(double now, bool trajectory_ended, double actual, double target) {
    if (window_.window == kWindowSwitchedOff) {
        return trajectory_ended;
    }
    const bool inside = trajectory_ended && std::abs(actual - target) <= window_.window;
    return timer_.update(now, inside);
}

} // namespace eposp::drives::motion
