#pragma once

#include "eposp/drives/escon2/protection/device_error_code.hpp"

#include <cstdint>
#include <vector>

namespace eposp::drives::escon2 {

/// The PWM measurement of digital input 1 or 2 (ESCON2 FW spec 6.2.31, 6.2.32, 7.1.30 - 7.1.35):
/// frequency and duty cycle from the pin's edges, each period measured at its closing rising
/// edge. Frequencies outside 50 Hz - 10 kHz raise the frequency warning and are shown limited
/// to that range; duty cycles are always limited to 10 - 90 %, with the duty cycle warning once
/// they leave that range by more than a slight threshold, until they are back inside it. A
/// pulse (high or low) shorter than 5 µs, or a signal gone unreadable, is the PWM error and
/// shows 0 Hz.
class PwmInput {
public:
    static constexpr double kMinFrequency = 50;     ///< Hz, 6.2.31
    static constexpr double kMaxFrequency = 10'000; ///< Hz
    static constexpr double kMinDutyCycle = 10;     ///< %, 6.2.32
    static constexpr double kMaxDutyCycle = 90;     ///< %
    static constexpr double kMinPulseWidth = 5e-6;  ///< s, 6.2.32: shorter is the PWM error
    /// "a slightly threshold until the warning appears" (6.2.32): the manual gives no figure.
    static constexpr double kDutyCycleWarningThreshold = 0.5; ///< % beyond 10 / 90 %
    /// "deviates too much ... and becomes unreadable" (6.2.31): no period closed for this long,
    /// five of the slowest valid period (a pin held at one level, a signal below 10 Hz).
    static constexpr double kUnreadableAfter = 0.1; ///< s
    /// Steps per % a duty cycle is measured in (a timer's resolution; 0x314C shows 0.1 %).
    static constexpr double kDutyCycleResolution = 1e6;

    /// The measurement of digital input `input` (1 or 2), started at `now` (s).
    PwmInput(unsigned input, double now);

    /// The pin's level from `now` on.
    void set_level(bool high, double now);
    /// Notices a signal that stopped; call once per step.
    void update(double now);

    /// 0x314B: the frequency in Hz, limited to 50 Hz - 10 kHz, 0 while the PWM error is present.
    double frequency() const;
    /// 0x314C: the duty cycle in %, limited to 10 - 90 %; the set value functions use it.
    double duty_cycle() const;
    /// 0x314B / 0x314C in their units (0.1 Hz, 0.1 %).
    std::uint32_t frequency_object() const;
    std::uint16_t duty_cycle_object() const;

    bool frequency_warning() const { return frequency_warning_; }
    bool duty_cycle_warning() const { return duty_cycle_warning_; }
    bool error() const { return error_; }
    /// The present conditions as the error codes of this input (table 110).
    std::vector<DeviceErrorCode> conditions() const;

private:
    void measure(double period, double high_time);

    unsigned input_;
    bool level_ = false;
    double last_rise_ = -1;
    double last_fall_ = -1;
    double last_period_end_;
    double frequency_ = 0;
    double duty_cycle_ = kMinDutyCycle;
    bool frequency_warning_ = false;
    bool duty_cycle_warning_ = false;
    bool error_ = false;
};

/// A steady PWM signal at a pin: rising edges at k / f, falling ones `duty_cycle` % later.
struct PwmSignal {
    double frequency = 1000; ///< Hz
    double duty_cycle = 50;  ///< %

    /// Feeds the edges of [from, to) into `input` (a wiring or a test driving the pin).
    void drive(PwmInput& input, double from, double to) const;
};

} // namespace eposp::drives::escon2
