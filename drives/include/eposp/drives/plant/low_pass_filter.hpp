#pragma once

#include <cmath>
#include <numbers>

namespace eposp::drives::plant {

/// A first-order digital low-pass filter, y[k] = y[k−1] + α·(x[k] − y[k−1]) with
/// α = 1 − e^(−2π·fc·Ts): the filter of the EPOS2's averaged actual values (FW spec 8.2.47,
/// 8.2.48).
class LowPassFilter {
public:
    LowPassFilter(double cutoff_hz, double sampling_time_s)
        : alpha_(1 - std::exp(-2 * std::numbers::pi * cutoff_hz * sampling_time_s)) {}

    void update(double input) { output_ += alpha_ * (input - output_); }
    double output() const { return output_; }
    void reset(double value = 0) { output_ = value; }

private:
    double alpha_;
    double output_ = 0;
};

} // namespace eposp::drives::plant
