#pragma once

#include "eposp/drives/motion/homing_method.hpp"
#include "eposp/drives/motion/trajectory.hpp"

#include <cstdint>
#include <optional>

namespace eposp::drives::motion {

/// The homing objects (EPOS2 FW spec 5.4.2.2) in drive units: quadcounts, quadcounts/s,
/// quadcounts/s² and amperes.
struct HomingParameters {
    HomingMethod method = HomingMethod::HomeSwitchPositiveIndex; ///< 0x6098 (default 7)
    double switch_search_speed = 0;                              ///< 0x6099 sub 1
    double zero_search_speed = 0;                                ///< 0x6099 sub 2
    double acceleration = 0;             ///< 0x609A, for every ramp up and down (5.4.1)
    RampShape shape = RampShape::Linear; ///< Motion Profile Type 0x6086
    std::int64_t home_offset = 0;        ///< 0x607C: moved from the reference at the end
    std::int64_t home_position = 0;      ///< 0x2081: what the home point then reads
    double current_threshold = 0;        ///< 0x2080, methods −1…−4
    std::int64_t counts_per_turn = 2000; ///< 4 × 0x2210 pulses: one index pulse per turn
};

/// What the drive senses in one control period.
struct HomingInputs {
    std::int64_t position = 0; ///< Position Actual Value
    bool negative_limit = false;
    bool positive_limit = false;
    bool home_switch = false;
    /// The position latched at an index pulse during the period, if one came.
    std::optional<std::int64_t> index_position;
    double current = 0; ///< Current Actual Value
};

/// Why a homing failed (statusword bit 13).
enum class HomingFailure {
    InvalidParameters,   ///< a speed, the acceleration or the current threshold not positive
    NegativeLimitSwitch, ///< reached where it is not the reference (or a second time)
    PositiveLimitSwitch,
    IndexNotFound, ///< no index within two turns (the limit of 4.2.24)
    DriveDisabled, ///< the drive function was lost (fault, disable) during the homing
};

/// The device error that accompanies a failure ("for error cause read error code", table 5-26),
/// where table 4-11 has one.
std::optional<std::uint16_t> error_code(HomingFailure failure);

/// One control period's result: the demand the position controller follows and, in the period
/// the homing completes, the offset to add to the position counter.
struct HomingStep {
    MotionState demand;
    std::optional<std::int64_t> position_offset;
};

/// Homing Mode (EPOS2 FW spec 5.4): the sequence of every method of table 8-121, fed each control
/// period with what the drive senses, producing the position demand of the homing trajectory
/// (5.4.1: ramps with the homing acceleration, the shape of 0x6086).
///
/// A sequence: search the reference with the switch search speed; from a switch, leave it again
/// with the zero search speed (its falling edge is the reference of methods 17…27); then, for
/// methods with index, go on at the zero search speed to the next index pulse; finally move the
/// home offset with the switch search speed. That point reads Home Position (0x2081) from then
/// on: the step that completes returns the offset to add to the position counter, and from that
/// step on demands and sensed positions are in the homed coordinates.
///
/// Home switch methods reverse once at a limit switch ahead (CiA 402 methods 7…14); any other
/// limit switch reached (ahead, or newly active) is an error, like an index that does not come
/// within two turns. Errors and halts stop on the homing acceleration. Times are seconds on the
/// caller's clock; positions quadcounts.
class HomingProcedure {
public:
    explicit HomingProcedure(double position = 0);

    /// Controlword bit 4 rising edge (table 5-23): start from the present demand `from`.
    void start(double now, const HomingParameters& parameters, const MotionState& from);
    /// Controlword bit 4 cleared during the homing: stop; the homing is neither attained nor in
    /// error.
    void interrupt(double now);
    /// Controlword bit 8 (table 5-23): stop with the homing acceleration. Released while bit 4
    /// is still set, the homing starts over from where the axis stopped.
    void set_halt(double now, bool halt);
    /// The drive function was lost during the homing (fault, disable): an error; the demand
    /// stays where it is, the stop is the device control's.
    void drive_disabled(double now);
    /// At rest at `position`, idle (e.g. the power stage enabled on the actual position).
    void reset(double position);

    HomingStep update(double now, const HomingInputs& sensed);

    /// Statusword bits 10, 12 and 13 in Homing Mode (table 5-26; the combinations of CiA 402).
    std::uint16_t statusword_bits(double now) const;
    /// Statusword bit 15 (8.2.86): set when a homing is attained, kept across modes.
    bool referenced() const { return referenced_; }
    /// The position counter overflowed or its sensor failed or was reconfigured (8.2.86, 8.2.74).
    void reference_lost() { referenced_ = false; }
    std::optional<HomingFailure> failure() const { return failure_; }
    /// Searching or moving home (not halted, not finished).
    bool in_progress() const;

private:
    enum class Phase {
        Idle,      ///< never started, or interrupted
        Beginning, ///< started (or restarted after halt); the next update picks the first move
        SearchingReference,
        LeavingSwitch,
        SearchingIndex,
        MovingToHome,
        Halted,
        Attained,
        Failed,
    };

    std::optional<std::int64_t> begin(double now, const HomingInputs& sensed);
    void search_reference(double now, const HomingInputs& sensed);
    void leave_switch(double now, const HomingInputs& sensed);
    void search_index(double now, const HomingInputs& sensed);
    std::optional<std::int64_t> move_to_home(double now, const HomingInputs& sensed);

    void leave_reference_switch(double now);
    void search_index_from(double now, std::int64_t position, int direction);
    void move_at(double now, double velocity);
    void start_home_move(double now, std::int64_t reference);
    std::int64_t complete(double now, std::int64_t home_point);
    void stop(double now, Phase next);
    void fail(double now, HomingFailure failure);
    bool limit_switch_ahead(const HomingInputs& sensed) const;
    std::optional<HomingFailure> limit_switch_hit(const HomingInputs& sensed,
                                                  HomingReference expected) const;
    bool reference_switch_active(const HomingInputs& sensed) const;
    bool started() const { return in_progress() || phase_ == Phase::Halted; }
    MotionState demand(double now) const { return trajectory_.sample(now - trajectory_start_); }
    bool at_rest(double now) const;

    HomingParameters parameters_;
    HomingMethodTraits traits_;
    Trajectory trajectory_;
    double trajectory_start_ = 0;
    Phase phase_ = Phase::Idle;
    int direction_ = 0;     ///< of the present search
    bool reversed_ = false; ///< a home switch search has turned at a limit switch
    std::int64_t index_search_start_ = 0;
    std::int64_t home_point_ = 0; ///< reference + home offset, before the position is re-zeroed
    HomingInputs previous_;       ///< the switches of the last period, for their edges
    std::optional<HomingFailure> failure_;
    bool halted_ = false;
    bool referenced_ = false;
};

} // namespace eposp::drives::motion
