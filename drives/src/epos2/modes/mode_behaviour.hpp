#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/drives/motion/homing_procedure.hpp"
#include "eposp/drives/motion/position_set_value_limiter.hpp"
#include "eposp/drives/motion/profile_planner.hpp"
#include "eposp/drives/motion/standstill_monitor.hpp"
#include "eposp/drives/plant/servo_axis.hpp"

#include <cstdint>
#include <functional>
#include <optional>

namespace eposp::drives::epos2 {

// EPOS2 FW spec 8.2.85, table 8-113: the controlword bits the operating modes own.
inline constexpr std::uint16_t kNewSetpointBit = 1U << 4; ///< PPM; homing operation start in HMM
inline constexpr std::uint16_t kChangeImmediatelyBit = 1U << 5;
inline constexpr std::uint16_t kRelativeBit = 1U << 6;
inline constexpr std::uint16_t kHaltBit = 1U << 8;
inline constexpr std::uint16_t kEndlessMovementBit = 1U << 15;

/// What the drive offers every mode: the dictionary its parameters and set values come from, the
/// units, the errors of table 4-11, and the parts whose state outlives a mode change.
struct ModeServices {
    const canopen::ObjectDictionary& objects;
    /// The same dictionary, for the read-only values a mode shows (IPM's buffer status).
    canopen::ObjectDictionary& outputs;
    const double& counts_per_turn;       ///< 4 × 0x2210 sub 1, kept up to date by the drive
    const double& rpm_per_velocity_unit; ///< 10^0x608B (3.3), kept up to date by the drive
    const std::int32_t& digital_position_counter; ///< inputs 2 and 3 (Epos2Drive)
    std::function<void(std::uint16_t)> raise_device_error;
    motion::HomingProcedure& homing;       ///< its reference (bit 15) survives mode changes
    motion::StandstillMonitor& standstill; ///< shared with the stop ramps (8.2.73)
    /// The limit and home switch functionalities now (polarity applied, not masked): asked for
    /// by the modes that use them (homing), when they do, not computed each period for all.
    std::function<plant::SwitchStates()> switches;

    /// rpm (0x6410 sub 4, 0x2101) or rpm/s (the acceleration unit, 3.3) to qc/s or qc/s².
    double rpm_to_counts(double rpm) const { return rpm * counts_per_turn / 60.0; }
    double counts_to_rpm(double counts) const { return counts * 60.0 / counts_per_turn; }
    /// [Velocity units] (3.3: rpm × 10^0x608B) to qc/s and back.
    double velocity_to_counts(double velocity) const {
        return rpm_to_counts(velocity * rpm_per_velocity_unit);
    }
    double counts_to_velocity(double counts) const {
        return counts_to_rpm(counts) / rpm_per_velocity_unit;
    }
    /// 5.3.2.1 / 5.10.2.1: 0x6081, 0x6083, 0x6084, 0x6086 clamped to 0x607F and 0x60C5.
    motion::ProfileParameters profile_parameters() const;
    /// The modes whose master gives the position (Position, Master Encoder, Step/Direction):
    /// `set_value` within the software limits 0x607D, followed by `limiter` within 0x607F and
    /// 0x60C5 for one control period (tables 5-37, 5-40, 5-43).
    motion::MotionState follow_position_set_value(motion::PositionSetValueLimiter& limiter,
                                                  double set_value) const;
};

/// The drive's measurements in a control period, in drive units.
struct ModeInputs {
    double now = 0; ///< s, the drive's clock
    std::uint16_t controlword = 0;
    std::int64_t position = 0; ///< Position Actual Value, quadcounts
    double velocity = 0;       ///< quadcounts/s, measured over the last millisecond
    double current = 0;        ///< A
    std::optional<std::int64_t> index_position{}; ///< an index pulse since the last period
};

/// A controlword written while the mode runs.
struct ControlwordChange {
    double now = 0;
    std::uint16_t controlword = 0;
    std::uint16_t rising = 0;
    std::uint16_t falling = 0;
    bool enabled = false;              ///< the drive function is enabled (Operation Enable)
    motion::MotionState last_demand{}; ///< of the last control period
};

/// What the mode commands for the next millisecond: a position demand for the position loop
/// (5.9), a velocity for the velocity loop (5.12) or a current for the current loop (5.14).
struct ModeDemand {
    motion::MotionState motion{}; ///< position (qc), velocity (qc/s), acceleration (qc/s²)
    plant::ControlMode loop = plant::ControlMode::Position;
    double current = 0;                            ///< A, the current loop's set value
    double speed_limit = 0;                        ///< qc/s in the current loop, 0 = none
    std::optional<std::int64_t> position_offset{}; ///< homing moved the position counter by this
};

/// One operating mode of table 8-118 (chapter 5): its demand generation, its controlword and
/// statusword bits, and what it does when it starts and when a stop of the device control ends.
/// The drive creates the mode when 0x6060 selects it or the power stage comes on, and runs the
/// device control's stop ramps (quickstop, slow-down, fault reaction) itself.
class ModeBehaviour {
public:
    virtual ~ModeBehaviour() = default;

    /// The mode starts at rest at `position` (the actual position); its parameters are read now.
    virtual void start(double now, std::int64_t position, bool power_stage_on) = 0;
    virtual void on_controlword(const ControlwordChange& change) = 0;
    /// A set value of the mode (see kSetValueObjects) was written, or set by the drive.
    virtual void on_set_value_written(double /*now*/, std::uint16_t /*index*/,
                                      std::uint8_t /*sub_index*/) {}
    /// The demand for this control period, before the plant steps.
    virtual ModeDemand demand(const ModeInputs& inputs) = 0;
    /// After the plant stepped: the mode's monitors (target reached, speed zero, …).
    virtual void watch(const ModeInputs& /*inputs*/, const motion::MotionState& /*demand*/) {}
    /// Table 8-114: the bits 10, 12, 13 the mode owns.
    virtual std::uint16_t statusword_bits(double now, bool following_error) const = 0;
    /// A stop ramp begins, or the power stage goes off (a running procedure is interrupted).
    virtual void drive_disabled(double /*now*/) {}
    /// A stop ramp of the device control has ended: start over at rest there, setpoints dropped.
    virtual void stop_completed(double position) = 0;
    /// 5.9.1.2: the following error is watched in the position-controlled modes.
    virtual bool position_controlled() const { return true; }
    /// 8.2.57, 8.2.105: limit switches and software limits raise errors (not while homing, where
    /// the switches are references and the limits mean nothing yet).
    virtual bool supervises_limits() const { return true; }
};

} // namespace eposp::drives::epos2
