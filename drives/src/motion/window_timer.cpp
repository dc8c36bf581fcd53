#include "eposp/drives/motion/window_timer.hpp"

namespace eposp::drives::motion {

bool WindowTimer::update(double now, bool inside) {
    if (!inside) {
        entered_.reset(); // leaving the window starts the time again
        return false;
    }
    if (!entered_) {
        entered_ = now;
    }
    // Control periods summed in floating point land a hair before the whole millisecond.
    constexpr double kTimeResolution = 1e-9;
    return now - *entered_ >= window_time_ - kTimeResolution;
}

} // namespace eposp::drives::motion
