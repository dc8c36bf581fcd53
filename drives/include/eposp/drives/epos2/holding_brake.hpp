#pragma once

#include "eposp/drives/motion/standstill_monitor.hpp"

#include <cstdint>

namespace eposp::drives::epos2 {

/// Holding Brake Configuration 0x2100 (EPOS2 FW spec 8.2.72) with its defaults, in ms.
struct HoldingBrakeTiming {
    std::uint16_t rise_time = 10;  ///< sub 1: brake unpowered until it holds
    std::uint16_t fall_time = 10;  ///< sub 2: brake powered until it lets go
    std::uint16_t timeout = 65535; ///< sub 3: engaged anyway after this; 65535 never
};

/// The holding brake in the enable and disable sequence (8.2.72, 8.2.73). It is present when an
/// output carries the holding brake functionality (0x2079 = 2); without one the power stage
/// follows the device control at once.
///
/// Enabling: the power stage comes on and the brake is released at once; Operation Enable is
/// reported only after the fall time, while the brake lets go (operation_may_start()).
/// Disabling from standstill (a stop ramp ended, or the axis was at rest): the brake engages at
/// once and the power stage holds the axis for the rise time, until the brake holds it. Disabling
/// a moving axis ("disable" option code, 8.2.87 / 8.2.88: no ramp), and any power-off in a fault
/// state: the power stage goes off at once and the brake engages when the axis comes to a
/// standstill (0x2101: Velocity Actual Value Averaged within the window for the window time), or
/// when the brake timeout elapses.
class HoldingBrake {
public:
    /// The standstill watch starts afresh (the brake's standstill is watched only while present).
    void configure(bool present, HoldingBrakeTiming timing, motion::StandstillWindow window);

    /// One control period: whether the power stage is on, given whether the device control wants
    /// it on, whether the drive is in a fault state, and Velocity Actual Value Averaged (rpm).
    bool power_stage(double now, bool requested, bool fault, double velocity_averaged);
    /// The brake's output functionality (0x2078 bit 2): 1 = brake engaged (unpowered).
    bool engaged() const { return phase_ == Phase::Off || phase_ == Phase::Engaging; }
    /// Whether the brake has let go for the fall time: Measure Init may end in Operation Enable.
    bool operation_may_start(double now) const;

private:
    enum class Phase {
        Off,      ///< power stage off, brake engaged
        Released, ///< power stage on, brake released since changed_
        Engaging, ///< brake engaged since changed_, power stage on for the rise time
        Coasting, ///< power stage off, brake waiting for standstill since changed_
    };
    void enter(Phase phase, double now);

    bool present_ = false;
    HoldingBrakeTiming timing_;
    motion::StandstillMonitor standstill_;
    Phase phase_ = Phase::Off;
    double changed_ = 0;
};

} // namespace eposp::drives::epos2
