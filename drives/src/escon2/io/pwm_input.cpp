#include "eposp/drives/escon2/io/pwm_input.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace eposp::drives::escon2 {

PwmInput::PwmInput(unsigned input, double now) : input_(input), last_period_end_(now) {
    if (input != 1 && input != 2) {
        throw std::out_of_range("PWM is measured on ESCON2 digital input 1 or 2, not " +
                                std::to_string(input));
    }
}

void PwmInput::set_level(bool high, double now) {
    if (high == level_) {
        return;
    }
    level_ = high;
    if (!high) {
        last_fall_ = now;
        return;
    }
    if (last_rise_ >= 0 && last_fall_ > last_rise_) {
        measure(now - last_rise_, last_fall_ - last_rise_);
        last_period_end_ = now;
    }
    last_rise_ = now;
}

void PwmInput::measure(double period, double high_time) {
    if (high_time < kMinPulseWidth || period - high_time < kMinPulseWidth) {
        error_ = true; // 6.2.32: a pulse shorter than 5 µs
        return;
    }
    error_ = false;
    // to the resolution of 0x314B (0.1 Hz): edge times in floating point are not exact
    frequency_ = std::round(10 / period) / 10;
    frequency_warning_ = frequency_ < kMinFrequency || frequency_ > kMaxFrequency;
    const double duty =
        std::round(100 * high_time / period * kDutyCycleResolution) / kDutyCycleResolution;
    if (duty < kMinDutyCycle - kDutyCycleWarningThreshold ||
        duty > kMaxDutyCycle + kDutyCycleWarningThreshold) {
        duty_cycle_warning_ = true;
    } else if (duty >= kMinDutyCycle && duty <= kMaxDutyCycle) {
        duty_cycle_warning_ = false;
    }
    duty_cycle_ = std::clamp(duty, kMinDutyCycle, kMaxDutyCycle);
}

void PwmInput::update(double now) {
    if (now - last_period_end_ > kUnreadableAfter) {
        error_ = true;
    }
}

double PwmInput::frequency() const {
    return error_ ? 0 : std::clamp(frequency_, kMinFrequency, kMaxFrequency);
}

double PwmInput::duty_cycle() const {
    return duty_cycle_;
}

std::uint32_t PwmInput::frequency_object() const {
    return static_cast<std::uint32_t>(std::lround(frequency() * 10));
}

std::uint16_t PwmInput::duty_cycle_object() const {
    return static_cast<std::uint16_t>(std::lround(duty_cycle() * 10));
}

std::vector<DeviceErrorCode> PwmInput::conditions() const {
    const bool first = input_ == 1;
    std::vector<DeviceErrorCode> codes;
    if (error_) {
        codes.push_back(first ? DeviceErrorCode::DigitalInput1PwmError
                              : DeviceErrorCode::DigitalInput2PwmError);
        return codes; // an unreadable signal has no frequency or duty cycle to warn about
    }
    if (frequency_warning_) {
        codes.push_back(first ? DeviceErrorCode::DigitalInput1PwmFrequencyWarning
                              : DeviceErrorCode::DigitalInput2PwmFrequencyWarning);
    }
    if (duty_cycle_warning_) {
        codes.push_back(first ? DeviceErrorCode::DigitalInput1PwmDutyCycleWarning
                              : DeviceErrorCode::DigitalInput2PwmDutyCycleWarning);
    }
    return codes;
}

void PwmSignal::drive(PwmInput& input, double from, double to) const {
    if (!(frequency > 0)) {
        return;
    }
    const double period = 1 / frequency;
    const double high_time = period * duty_cycle / 100;
    for (double k = std::floor(from / period); k * period < to; ++k) {
        const double rise = k * period;
        if (rise >= from && high_time > 0) {
            input.set_level(true, rise);
        }
        const double fall = rise + high_time;
        if (fall >= from && fall < to && high_time < period) {
            input.set_level(false, fall);
        }
    }
}

} // namespace eposp::drives::escon2
