#pragma once

#include "eposp/drives/motion/pvt_segment.hpp"
#include "eposp/drives/motion/target_reached_monitor.hpp"
#include "eposp/drives/motion/trajectory.hpp"
#include "interpolation_buffer.hpp"
#include "mode_behaviour.hpp"

#include <optional>

namespace eposp::drives::epos2 {

/// Interpolated Position Mode (EPOS2 FW spec 5.5, operating mode 7): PVT reference points
/// written to 0x20C1 queue in the 64-record FIFO (access enabled by 0x60C4 sub 6); controlword
/// bit 4 starts the cubic interpolation (5.5.1) from the present demand through the queued points,
/// each record being a segment's end point and duration. A record with time 0 ends it without
/// error; a FIFO holding fewer than two records when a segment begins, a record written to a full
/// FIFO, or a velocity / acceleration above 0x607F / 0x60C5 aborts it with the IPM error 0xFF0C
/// (table 8-100 says which). Halt (bit 8) stops the axis with the profile deceleration.
///
/// The FIFO belongs to the mode: selecting the mode clears it (5.5.5, transition I), and so does
/// switching the power stage on, which starts the mode afresh.
class InterpolatedPositionMode final : public ModeBehaviour {
public:
    explicit InterpolatedPositionMode(ModeServices& services);

    void start(double now, std::int64_t position, bool power_stage_on) override;
    void on_controlword(const ControlwordChange& change) override;
    void on_set_value_written(double now, std::uint16_t index, std::uint8_t sub_index) override;
    ModeDemand demand(const ModeInputs& inputs) override;
    void watch(const ModeInputs& inputs, const motion::MotionState& demand) override;
    std::uint16_t statusword_bits(double now, bool following_error) const override;
    void drive_disabled(double now) override;
    void stop_completed(double position) override;

private:
    void activate(double now);
    /// Begins the segment to the next record at `now`; the motion ends at a record of time 0.
    void next_segment(double now);
    /// Trajectory abort: the flag of table 8-100, interpolation inactive, error 0xFF0C.
    void abort(std::uint16_t error_flag);
    /// Table 8-100: the interpolated velocity and acceleration against 0x6081/0x6083 (warnings)
    /// and 0x607F/0x60C5 (errors).
    void check_limits(const motion::MotionState& state);
    /// 0x20C4 sub 1, 0x60C4 sub 2 (free records) and sub 4 (records queued).
    void show_buffer();

    ModeServices& services_;
    InterpolationBuffer buffer_;
    bool active_ = false;
    std::optional<motion::PvtSegment> segment_;
    double segment_start_ = 0;
    motion::MotionState last_demand_{};
    std::optional<motion::Trajectory> halt_; ///< the ramp to rest of a halt
    double halt_start_ = 0;
    motion::TargetReachedMonitor target_reached_{motion::TargetWindow{}};
    bool target_reached_now_ = false;
};

} // namespace eposp::drives::epos2
