#pragma once

namespace eposp::drives::escon2 {

/// The set value functions and monitor scalings of ESCON2 FW spec 6.2.44 - 6.2.54: a straight
/// line through a first and a second slope point (duty cycle, voltage, velocity, current or
/// temperature in; set value or voltage out). Identical inputs are "invalid scaling settings"
/// and give the first point's value. The line continues beyond the two points; what limits
/// the result is the range of the input (PWM 10 - 90 %, the analog input) or of the output.
struct TwoPointScaling {
    double first_input = 0;
    double first_value = 0;
    double second_input = 1;
    double second_value = 0;

    double apply(double input) const;
};

} // namespace eposp::drives::escon2
