#include "eposp/drives/motion/i2t_current_limit.hpp"

#include <algorithm>
#include <cmath>

namespace eposp::drives::motion {

void I2tCurrentLimit::update(double current, double dt) {
    if (parameters_.continuous_current <= 0) {
        load_ = current == 0 ? 0 : 1; // no continuous current at all: limited to 0 at once
        return;
    }
    const double ratio = current / parameters_.continuous_current;
    // The first-order heating, exact for a current constant over dt.
    if (dt != gain_dt_) {
        gain_dt_ = dt;
        gain_ = -std::expm1(-dt / parameters_.time_constant);
    }
    load_ += (ratio * ratio - load_) * gain_;
}

double I2tCurrentLimit::limit() const {
    return limiting() ? std::min(parameters_.continuous_current, parameters_.output_current_limit)
                      : parameters_.output_current_limit;
}

} // namespace eposp::drives::motion
