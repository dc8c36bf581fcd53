#pragma once

#include <optional>

namespace eposp::drives::motion {

/// A condition that counts only once it has held without a break for a window time (EPOS2 FW
/// spec 8.2.96 Position Window Time, 8.2.101 Velocity Window Time, 8.2.73 Standstill Window
/// Time). Times in seconds on the caller's clock.
class WindowTimer {
public:
    explicit WindowTimer(double window_time) : window_time_(window_time) {}

    /// Whether the condition, sampled `inside` at `now`, has held for the window time.
    bool update(double now, bool inside);
    void reset() { entered_.reset(); }

private:
    double window_time_;
    std::optional<double> entered_;
};

} // namespace eposp::drives::motion
