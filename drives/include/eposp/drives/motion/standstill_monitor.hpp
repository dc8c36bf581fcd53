#pragma once

#include "eposp/drives/motion/window_timer.hpp"

#include <cstdint>
#include <optional>

namespace eposp::drives::motion {

/// The value of 0x2101 sub 1 or sub 3 that switches the window or the timeout off (8.2.73).
inline constexpr std::uint16_t kStandstillSwitchedOff = 65535;

/// Standstill Window Configuration 0x2101 (EPOS2 FW spec 8.2.73) with its defaults.
struct StandstillWindow {
    std::uint16_t window = 30;       ///< sub 1: |velocity| at most this, in velocity units
    std::uint16_t time_ms = 50;      ///< sub 2: for this long
    std::uint16_t timeout_ms = 1000; ///< sub 3: a stop counts as completed after this anyway
};

/// Standstill (8.2.73): Velocity Actual Value Averaged within the standstill window for the
/// window time; with the window switched off, the end of the trajectory. It serves the PVM
/// statusword bit 12 "speed is equal 0" (table 5-54; the EPOS2 has no velocity threshold object
/// 0x606F, so its own standstill definition decides) and the end of a stop ramp in Quickstop
/// Active, Fault Reaction Active and a slowed-down disable, where the timeout prevents a hang.
class StandstillMonitor {
public:
    explicit StandstillMonitor(StandstillWindow window = {});

    /// Whether the axis stands still; `trajectory_ended`: the demand has come to rest.
    bool update(double now, double velocity_averaged, bool trajectory_ended);

    /// A stop ramp begins; stop_completed() then also turns true after the timeout.
    void stop_started(double now) { stop_started_ = now; }
    /// Standstill reached since the stop started, or the timeout elapsed.
    bool stop_completed(double now) const;

private:
    StandstillWindow window_;
    WindowTimer timer_;
    bool standstill_ = false;
    std::optional<double> stop_started_;
};

} // namespace eposp::drives::motion
