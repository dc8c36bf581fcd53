#include "eposp/drives/motion/following_error_monitor.hpp"

#include "eposp/drives/motion/device_error_codes.hpp"

#include <cmath>

namespace eposp::drives::motion {

std::optional<std::uint16_t> FollowingErrorMonitor::update(double demand, double actual) {
    const bool was_active = active_;
    active_ = max_ != kFollowingControlOff && std::abs(demand - actual) > max_;
    if (active_ && !was_active) {
        return kFollowingErrorCode; // raised once; the fault reaction takes it from there
    }
    return std::nullopt;
}

} // namespace eposp::drives::motion
