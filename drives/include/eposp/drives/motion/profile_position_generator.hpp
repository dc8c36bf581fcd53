#pragma once

#include "eposp/drives/motion/profile_planner.hpp"

#include <optional>

namespace eposp::drives::motion {

/// A Profile Position setpoint as the master gives it (EPOS2 FW spec 5.3.2.2/5.3.2.3).
struct PositionSetpoint {
    double target = 0;
    bool relative = false; ///< controlword bit 6: Pend = position demand value + target
    ProfileParameters parameters;
    /// Controlword bit 15: move on at the profile velocity, in the direction of the target's
    /// sign, until another setpoint, halt or quickstop.
    bool endless = false;
};

/// The Profile Position trajectory generator (5.3.1) with its setpoint handling (5.3.2.3): a new
/// setpoint either interrupts the present move ("change set immediately", re-planned from the
/// moving state) or waits in a one-deep buffer until the present move has finished. Halt and
/// quickstop stop on their ramps; releasing halt resumes the move. Times are seconds on any
/// monotonic clock of the caller's; the generator has none of its own.
class ProfilePositionGenerator {
public:
    explicit ProfilePositionGenerator(double position = 0);

    /// A new setpoint (rising edge of controlword bit 4). Returns false, leaving everything as
    /// it was, when a buffered setpoint already waits: the setpoint is not acknowledged.
    bool new_setpoint(double now, const PositionSetpoint& setpoint, bool change_immediately);

    /// Controlword bit 8 (5.3.2.3): stop with the profile deceleration; released, continue.
    void set_halt(double now, bool halt);
    /// Quickstop: stop with the quickstop deceleration 0x6085 and drop every setpoint.
    void quick_stop(double now, double deceleration, RampShape shape);
    /// Start over at rest at `position` (e.g. power stage enabled on the actual position).
    void reset(double position);

    /// The position demand value and its derivatives at `now`; starts a buffered setpoint once
    /// the present move is over. Call with non-decreasing times.
    MotionState update(double now);

    /// True while a buffered setpoint waits (statusword bit 12 stays set: no room for another).
    bool buffer_full() const { return buffered_.has_value(); }
    /// The present move (or stop) has come to rest and nothing waits.
    bool finished(double now) const;
    /// The end position of the present move (the target, or where a stop ends).
    double demand_target() const { return trajectory_.final_position(); }

private:
    void start(double now, const MotionState& from, const PositionSetpoint& setpoint);
    bool at_rest(double now) const;

    Trajectory trajectory_;
    double start_time_ = 0;
    std::optional<PositionSetpoint> buffered_;
    std::optional<PositionSetpoint> active_;
    bool halted_ = false;
};

} // namespace eposp::drives::motion
