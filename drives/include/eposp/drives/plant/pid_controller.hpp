#pragma once

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

    double update(double error, double dt, double feed_forward = 0);
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
