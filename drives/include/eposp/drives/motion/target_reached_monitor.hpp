#pragma once

#include "eposp/drives/motion/window_timer.hpp"

#include <cstdint>

namespace eposp::drives::motion {

/// The window value that switches a window off (8.2.95, 8.2.100: 2^32 − 1).
inline constexpr std::uint32_t kWindowSwitchedOff = 0xFFFFFFFF;

/// A window around a target and its window time, as the dictionary holds them: Position Window
/// 0x6067 / Position Window Time 0x6068 (PPM), Velocity Window 0x606D / Velocity Window Time
/// 0x606E (PVM).
struct TargetWindow {
    std::uint32_t window = kWindowSwitchedOff; ///< half-width, in the units of the values compared
    std::uint16_t time_ms = 0;
};

/// Statusword bit 10 "target reached" with halt off (EPOS2 FW spec 5.3, figure 5-7; 5.10, figure
/// 5-33): reached once the trajectory has ended and the actual value has stayed within the window
/// around the target for the window time. The window is watched only after the trajectory has
/// ended, or a move shorter than the window would count as reached when it starts. With the
/// window switched off, the end of the trajectory is the target reached.
class TargetReachedMonitor {
public:
    explicit TargetReachedMonitor(TargetWindow window);

    /// `actual`: Position Actual Value (PPM) or Velocity Actual Value Averaged (PVM).
    bool update(double now, bool trajectory_ended, double actual, double target);
    void reset() { timer_.reset(); }

private:
    TargetWindow window_;
    WindowTimer timer_;
};

} // namespace eposp::drives::motion
