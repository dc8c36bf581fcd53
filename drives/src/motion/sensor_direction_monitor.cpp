#include "eposp/drives/motion/sensor_direction_monitor.hpp"

#include <cstdlib>

namespace eposp::drives::motion {

bool SensorDirectionMonitor::update(double motor_speed, std::int64_t position) {
    const std::int64_t moved = position - position_;
    position_ = position;
    if (motor_speed == 0) {
        against_ = 0;
    } else if (moved != 0) {
        against_ = (moved > 0) == (motor_speed > 0) ? 0 : against_ + std::abs(moved);
    }
    return against_ >= limit_;
}

} // namespace eposp::drives::motion
