#pragma once

#include <algorithm>

namespace eposp::drives::plant {

/// A discrete PID law with feed-forward, a symmetric output limit and anti-windup by
/// conditional integration (the integral only grows while the output is not saturated).
class PidController {
public:
    struct Gains {
        double kp = 0;
        double ki = 0; ///< per second
        double kd = 0; ///< seconds; derivative of the error between two updates
    };

    PidController(Gains gains, double output_limit) : gains_(gains), limit_(output_limit) {}

    /// Inline: the current loop runs it every 0.1 ms of every axis.
    double update(double error, double dt, double feed_forward = 0) {
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
    void reset();
    /// Takes over from another source of the output without a bump: the integral becomes it.
    void preset(double output) {
        integral_ = output;
        has_previous_ = false;
    }
    /// New gains and limit from the next update on; the integral carries on (no bump).
    void retune(Gains gains, double output_limit) {
        gains_ = gains;
        limit_ = output_limit;
    }

private:
    Gains gains_;
    double limit_;
    double integral_ = 0;
    double previous_error_ = 0;
    bool has_previous_ = false;
};

} // namespace eposp::drives::plant
