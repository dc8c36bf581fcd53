#include "eposp/drives/motion/standstill_monitor.hpp"

#include <cmath>

namespace eposp::drives::motion {

StandstillMonitor::StandstillMonitor(StandstillWindow window)
    : window_(window), timer_(window.time_ms * 1e-3) {}

bool StandstillMonitor::update(double now, double velocity_averaged, bool trajectory_ended) {
    standstill_ = window_.window == kStandstillSwitchedOff
                      ? trajectory_ended
                      : timer_.update(now, std::abs(velocity_averaged) <= window_.window);
    return standstill_;
}

bool StandstillMonitor::stop_completed(double now) const {
    if (standstill_) {
        return true;
    }
    return stop_started_ && window_.timeout_ms != kStandstillSwitchedOff &&
           now - *stop_started_ >= window_.timeout_ms * 1e-3;
}

} // namespace eposp::drives::motion
