#pragma once

#include "eposp/plcopen/axis_link.hpp"
#include "eposp/plcopen/axis_state.hpp"
#include "eposp/plcopen/motion_command.hpp"

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace eposp::plcopen {

/// One axis as the motion blocks drive it: the PLCopen state diagram on top of the CiA 402
/// device control and profile modes of its drive (EPOS2 firmware specification, chapters 3 and
/// 5). The blocks call it during a PLC cycle; it works only from what the link reported at the
/// last SYNC and never waits: parameters go out by SDO and are confirmed by callback, set-points
/// by the new set-point / set-point acknowledge handshake over the process data.
///
/// - MC_Power's request enables the drive (shutdown, then switch on + enable operation) and
///   takes the axis from Disabled to Standstill once the drive reports Operation enabled;
///   withdrawn, it shuts the drive down and the axis is Disabled (from any state but
///   ErrorStop).
/// - A drive fault, or a slave that was ready and is lost, takes the axis to ErrorStop from any
///   state; the commands it ran fail. Only reset() leaves ErrorStop: a fault reset
///   (controlword bit 7), then Disabled, from where a standing power request enables again.
/// - Commands run one at a time. Aborting ones replace what runs and what waits; Buffered
///   ones wait until the command before is done. A Buffered position move after a position
///   move waits in the drive's set-point buffer, so the drive starts it the moment the one
///   before ends. Stop cannot be aborted: while it runs and until release_stop(), everything
///   else is refused.
class AxisDriver {
public:
    AxisDriver(AxisLink& link, AxisNumber axis);
    ~AxisDriver();
    AxisDriver(const AxisDriver&) = delete;
    AxisDriver& operator=(const AxisDriver&) = delete;

    AxisNumber number() const { return axis_; }
    AxisState state() const { return state_; }
    /// Why the axis went to ErrorStop (None outside ErrorStop).
    ErrorId axis_error() const { return axis_error_; }
    /// The drive's error code, from the newest entry of its error history 0x1003 when it faulted
    /// (0 until then).
    std::uint16_t drive_error_code() const { return drive_error_code_; }
    AxisPresence presence() const { return link_.presence(axis_); }
    std::int32_t actual_position() const { return link_.actual_position(axis_); }
    /// Operation enabled and not in ErrorStop: MC_Power's Status.
    bool powered() const;

    /// Brings the driver up to date with the link: the state diagram and the running command.
    /// Every other call does it first; a block calls it to see this cycle's state.
    void poll();

    /// MC_Power's Enable, held until changed.
    void request_power(bool enable);
    /// Starts `command` now (Aborting) or after the commands before it (Buffered); refused with
    /// an ErrorID when the state does not accept it.
    Submitted submit(const MotionCommand& command, BufferMode mode);
    CommandReport report(CommandId id) const;
    /// MC_Stop's Execute fell: once its stop is done the axis is in Standstill again.
    void release_stop(CommandId id);
    /// MC_Reset: leaves ErrorStop. Done (Active false) when the axis is out of ErrorStop.
    Submitted reset();

private:
    struct Running;
    struct Step;

    void follow_power(std::uint16_t statusword);
    void enter_error_stop(ErrorId error);
    void start(CommandId id, const MotionCommand& command);
    /// The command with the SDO steps it needs before its set-point.
    std::unique_ptr<Running> prepare(CommandId id, const MotionCommand& command) const;
    Running* find(CommandId id) const;
    void advance(std::uint16_t statusword);
    void hand_on(std::uint16_t statusword);
    void advance_reset(std::uint16_t statusword);
    void issue(const Running& owner, const Step& step);
    bool steps_done(Running& running);
    /// A position move's target; `start` is where a relative one counts from.
    std::int32_t target_of(const MotionCommand& command, std::int32_t start) const;
    void finish(CommandStatus status, ErrorId error = ErrorId::None);
    void abort_all(CommandStatus status, ErrorId error);
    void record(CommandId id, CommandReport report);
    bool answered() const; ///< the statusword answers the last controlword change
    void send_controlword();

    AxisLink& link_;
    AxisNumber axis_;
    AxisState state_ = AxisState::Disabled;
    ErrorId axis_error_ = ErrorId::None;
    std::uint16_t drive_error_code_ = 0;
    bool power_requested_ = false;
    bool seen_ready_ = false;
    std::uint16_t device_bits_ = 0;     ///< controlword bits of device control (0..3, 7)
    std::uint16_t mode_bits_ = 0;       ///< controlword bits of the mode (4..6, 8)
    std::optional<std::uint16_t> sent_; ///< the controlword last given to the link
    std::uint32_t changed_at_ = 0;      ///< samples() when it changed
    std::uint32_t next_id_ = 1;
    std::int8_t mode_ = 0; ///< the mode of operation the drive confirmed, 0 unknown
    std::optional<std::int32_t> last_target_;
    std::unique_ptr<Running> running_;
    std::unique_ptr<Running> next_; ///< the Buffered move handed on to the drive's buffer
    std::deque<std::pair<CommandId, MotionCommand>> waiting_;
    std::deque<std::pair<CommandId, CommandReport>> finished_;
    CommandId stop_ = 0;         ///< the stop that holds the axis in Stopping
    bool stop_released_ = false; ///< its Execute fell while it ran
    CommandId reset_ = 0;
    bool reset_pulsed_ = false;
    /// Expires with the driver: SDO replies that arrive later are dropped.
    std::shared_ptr<bool> alive_;
};

} // namespace eposp::plcopen
