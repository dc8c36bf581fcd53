#include "eposp/drives/plant/pid_controller.hpp"

#include <algorithm>

namespace eposp::drives::plant {

double PidController::update(double error, double dt, double feed_forward) {
    const double derivative = has_previous_ ? (error - previous_error_) / dt : 0;
    previous_error_ = error;
    has_previous_ = true;
    const double integral = integral_ + gains_.ki * error * dt;
    const double output = gains_.kp * error + integral + gains_.kd * derivative + feed_forward;
    if (output > limit_ || output < -limit_) {
        return std::clamp(output - integral + integral_, -limit_, limit_);
    }
    integral_ = integral;
    return output;
}

void PidController::reset() {
    integral_ = 0;
    previous_error_ = 0;
    has_previous_ = false;
}

} // namespace eposp::drives::plant
