#pragma once

namespace eposp::drives::escon2 {

/// The software filter of a digital input (ESCON2 FW spec 4.1.1): "The input level needs to stay
/// steady for longer than the filter time in order to detect a state change (edge)". Exact in
/// virtual time: a level held for longer than the filter time is taken, a shorter spike never.
class DebouncedInput {
public:
    /// 4.1.1: 1 ms for regular digital inputs, 500 µs for high-speed ones.
    static constexpr double kRegularFilterTime = 1e-3;
    static constexpr double kHighSpeedFilterTime = 500e-6;

    explicit DebouncedInput(double filter_time) : filter_time_(filter_time) {}

    /// The pin's level from `now` (s) on.
    void set_level(bool high, double now);
    /// The filtered level at `now`.
    bool level(double now);
    /// The unfiltered level at the pin.
    bool pin() const { return pin_; }

private:
    void settle(double now);

    double filter_time_;
    bool pin_ = false;
    bool filtered_ = false;
    double since_ = 0; ///< when the pin took its level
};

} // namespace eposp::drives::escon2
