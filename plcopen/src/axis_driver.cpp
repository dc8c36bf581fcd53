#include "eposp/plcopen/axis_driver.hpp"

#include "cia402.hpp"

#include <algorithm>

namespace eposp::plcopen {

namespace {

/// How many outcomes a driver remembers for blocks that have not asked yet.
constexpr std::size_t kRememberedOutcomes = 64;
/// Reads of 0x6061 before a mode written to 0x6060 counts as refused.
constexpr int kModeConfirmations = 20;

bool is_position_move(MotionCommand::Kind kind) {
    using K = MotionCommand::Kind;
    return kind == K::MoveAbsolute || kind == K::MoveRelative || kind == K::MoveAdditive;
}

std::int8_t mode_of(MotionCommand::Kind kind) {
    using K = MotionCommand::Kind;
    switch (kind) {
    case K::MoveVelocity:
        return cia402::kProfileVelocity;
    case K::Home:
        return cia402::kHoming;
    case K::Halt:
    case K::Stop:
        return 0; // halts in whatever mode runs
    default:
        return cia402::kProfilePosition;
    }
}

AxisState state_running(MotionCommand::Kind kind) {
    using K = MotionCommand::Kind;
    switch (kind) {
    case K::MoveVelocity:
        return AxisState::ContinuousMotion;
    case K::Home:
        return AxisState::Homing;
    case K::Stop:
        return AxisState::Stopping;
    default:
        return AxisState::DiscreteMotion;
    }
}

} // namespace

std::string_view name(AxisState state) {
    switch (state) {
    case AxisState::Disabled:
        return "Disabled";
    case AxisState::Standstill:
        return "Standstill";
    case AxisState::Homing:
        return "Homing";
    case AxisState::DiscreteMotion:
        return "DiscreteMotion";
    case AxisState::ContinuousMotion:
        return "ContinuousMotion";
    case AxisState::Stopping:
        return "Stopping";
    case AxisState::ErrorStop:
        break;
    }
    return "ErrorStop";
}

/// One SDO transfer a command needs before its set-point.
struct AxisDriver::Step {
    bool confirm_mode = false; ///< read 0x6061 until it equals `value`
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    std::uint32_t value = 0;
    std::uint8_t size = 4;
};

struct AxisDriver::Running {
    enum class Phase { Steps, Setpoint, Acknowledge, Moving };

    CommandId id = 0;
    MotionCommand command;
    Phase phase = Phase::Steps;
    std::vector<Step> steps;
    std::size_t confirmed = 0; ///< steps completed
    bool issued = false;       ///< the steps are on their way
    int confirmations = 0;
    std::optional<Step> reread;     ///< the mode was not confirmed yet: ask again
    std::optional<ErrorId> failure; ///< a step failed (set by its callback)
    std::int32_t target = 0;
    bool in_velocity = false;
};

AxisDriver::AxisDriver(AxisLink& link, AxisNumber axis)
    : link_(link), axis_(axis), alive_(std::make_shared<bool>(true)) {}

AxisDriver::~AxisDriver() = default;

bool AxisDriver::powered() const {
    return state_ != AxisState::ErrorStop && state_ != AxisState::Disabled &&
           cia402::is_operation_enabled(link_.statusword(axis_));
}

bool AxisDriver::answered() const {
    return link_.samples(axis_) - changed_at_ >= 2;
}

void AxisDriver::poll() {
    const AxisPresence presence = link_.presence(axis_);
    const std::uint16_t statusword = link_.statusword(axis_);
    seen_ready_ = seen_ready_ || presence == AxisPresence::Ready;
    if (state_ != AxisState::ErrorStop) {
        if (presence != AxisPresence::Ready && seen_ready_) {
            enter_error_stop(ErrorId::CommunicationLost);
        } else if (presence == AxisPresence::Ready && cia402::is_fault(statusword)) {
            enter_error_stop(ErrorId::DriveFault);
        }
    }
    if (state_ == AxisState::ErrorStop) {
        advance_reset(statusword);
    } else {
        follow_power(statusword);
        if (running_ && state_ != AxisState::Disabled) {
            advance(statusword);
        }
    }
    send_controlword();
}

void AxisDriver::request_power(bool enable) {
    power_requested_ = enable;
    poll();
}

void AxisDriver::follow_power(std::uint16_t statusword) {
    if (!power_requested_) {
        device_bits_ = cia402::kShutdown;
        if (state_ != AxisState::Disabled) {
            abort_all(CommandStatus::Aborted, ErrorId::None);
            state_ = AxisState::Disabled;
        }
        return;
    }
    device_bits_ =
        cia402::is_switch_on_disabled(statusword) ? cia402::kShutdown : cia402::kEnableOperation;
    if (!answered()) {
        return;
    }
    if (state_ == AxisState::Disabled && cia402::is_operation_enabled(statusword)) {
        state_ = AxisState::Standstill;
    } else if (state_ != AxisState::Disabled && !cia402::is_operation_enabled(statusword)) {
        // Enabled, then no longer, without a fault: a quick stop from the drive's inputs.
        enter_error_stop(ErrorId::DriveFault);
    }
}

void AxisDriver::enter_error_stop(ErrorId error) {
    abort_all(CommandStatus::Failed, error);
    state_ = AxisState::ErrorStop;
    axis_error_ = error;
    mode_bits_ = 0;
    // The drive stops on its quick-stop ramp if it still can; a faulted one already has.
    device_bits_ = cia402::kQuickStop;
    mode_ = 0;
    if (error == ErrorId::DriveFault) {
        std::weak_ptr<bool> alive = alive_;
        // The newest entry of the drive's error history (the EPOS2 has no 0x603F).
        link_.read(axis_, 0x1003, 1, [this, alive](const SdoReply& reply) {
            if (!alive.expired() && reply.abort_code == 0) {
                drive_error_code_ = static_cast<std::uint16_t>(reply.value);
            }
        });
    }
}

Submitted AxisDriver::submit(const MotionCommand& command, BufferMode mode) {
    poll();
    using K = MotionCommand::Kind;
    if (link_.presence(axis_) == AxisPresence::Unassigned) {
        return {.error = ErrorId::UnknownAxis};
    }
    if (state_ == AxisState::ErrorStop) {
        return {.error = ErrorId::AxisInErrorStop};
    }
    if (state_ == AxisState::Disabled ||
        (state_ == AxisState::Stopping && command.kind != K::Stop) ||
        (command.kind == K::Home && state_ != AxisState::Standstill)) {
        return {.error = ErrorId::NotAllowed};
    }
    const CommandId id = (static_cast<CommandId>(axis_) << 24) | (next_id_++ & 0xFFFFFF);
    if (mode == BufferMode::Aborting || command.kind == K::Stop || !running_) {
        abort_all(CommandStatus::Aborted, ErrorId::None);
        start(id, command);
    } else {
        waiting_.emplace_back(id, command);
    }
    poll();
    return {.id = id};
}

void AxisDriver::start(CommandId id, const MotionCommand& command) {
    running_ = prepare(id, command);
    state_ = state_running(command.kind);
    if (command.kind == MotionCommand::Kind::Stop) {
        stop_ = id;
        stop_released_ = false;
    }
    // A new set-point or homing start is a rising edge: the bit goes low first. Halt stays as
    // it is until the set-point, or a halted move would resume meanwhile.
    mode_bits_ &= cia402::kHalt;
}

std::unique_ptr<AxisDriver::Running> AxisDriver::prepare(CommandId id,
                                                         const MotionCommand& command) const {
    auto running = std::make_unique<Running>();
    running->id = id;
    running->command = command;
    auto& steps = running->steps;
    if (const std::int8_t mode = mode_of(command.kind); mode != 0 && mode != mode_) {
        steps.push_back({.index = 0x6060, .value = static_cast<std::uint8_t>(mode), .size = 1});
        steps.push_back({.confirm_mode = true, .value = static_cast<std::uint8_t>(mode)});
    }
    const auto u32 = [](std::int32_t value) {
        return static_cast<std::uint32_t>(value);
    };
    using K = MotionCommand::Kind;
    switch (command.kind) {
    case K::MoveAbsolute:
    case K::MoveRelative:
    case K::MoveAdditive:
        steps.push_back({.index = 0x6081, .value = u32(command.velocity)});
        steps.push_back({.index = 0x6083, .value = u32(command.acceleration)});
        steps.push_back({.index = 0x6084, .value = u32(command.deceleration)});
        break;
    case K::MoveVelocity:
        steps.push_back({.index = 0x6083, .value = u32(command.acceleration)});
        steps.push_back({.index = 0x6084, .value = u32(command.deceleration)});
        steps.push_back({.index = 0x60FF, .value = u32(command.velocity)});
        break;
    case K::Halt:
    case K::Stop:
        steps.push_back({.index = 0x6084, .value = u32(command.deceleration)});
        break;
    case K::Home:
        if (command.homing_method != 0) { // 0: the method the drive is configured with
            steps.push_back({.index = 0x6098,
                             .value = static_cast<std::uint8_t>(command.homing_method),
                             .size = 1});
        }
        steps.push_back({.index = 0x2081, .value = u32(command.position)});
        break;
    }
    return running;
}

AxisDriver::Running* AxisDriver::find(CommandId id) const {
    for (Running* running : {running_.get(), next_.get()}) {
        if (running != nullptr && running->id == id) {
            return running;
        }
    }
    return nullptr;
}

void AxisDriver::issue(const Running& owner, const Step& step) {
    std::weak_ptr<bool> alive = alive_;
    auto done = [this, alive, id = owner.id, step](const SdoReply& reply) {
        Running* running = alive.expired() ? nullptr : find(id);
        if (running == nullptr || running->failure) {
            return;
        }
        if (reply.abort_code != 0) {
            running->failure = ErrorId::SdoAbort;
        } else if (!step.confirm_mode) {
            ++running->confirmed;
        } else if (static_cast<std::int8_t>(reply.value) == static_cast<std::int8_t>(step.value)) {
            mode_ = static_cast<std::int8_t>(step.value);
            ++running->confirmed;
        } else if (++running->confirmations >= kModeConfirmations) {
            running->failure = ErrorId::ModeNotConfirmed;
        } else {
            running->reread = step; // the drive may switch later: read 0x6061 again
        }
    };
    if (step.confirm_mode) {
        link_.read(axis_, 0x6061, 0, std::move(done));
    } else {
        link_.write(axis_, step.index, step.sub_index, step.value, step.size, std::move(done));
    }
}

bool AxisDriver::steps_done(Running& running) {
    // Requests to one drive run in order (SdoClient queues them): all go out at once.
    if (!running.issued) {
        running.issued = true;
        for (const Step& step : running.steps) {
            issue(running, step);
        }
    }
    if (running.reread) {
        issue(running, *std::exchange(running.reread, std::nullopt));
    }
    return running.confirmed == running.steps.size();
}

std::int32_t AxisDriver::target_of(const MotionCommand& command, std::int32_t start) const {
    switch (command.kind) {
    case MotionCommand::Kind::MoveAbsolute:
        return command.position;
    case MotionCommand::Kind::MoveRelative:
        return start + command.position;
    default: // MoveAdditive: from the last commanded target
        return last_target_.value_or(start) + command.position;
    }
}

// 5.3.2.3: with "change set immediately" clear, the drive keeps one set-point in a buffer and
// starts it the moment the present move ends. A Buffered position move goes there while the
// move before it runs, so the axis goes on without waiting a PLC cycle at the target.
void AxisDriver::hand_on(std::uint16_t statusword) {
    using Phase = Running::Phase;
    if (!next_) {
        if (waiting_.empty() || !is_position_move(waiting_.front().second.kind)) {
            return;
        }
        const auto [id, command] = waiting_.front();
        waiting_.pop_front();
        next_ = prepare(id, command);
    }
    Running& next = *next_;
    if (next.failure) {
        record(next.id, {.status = CommandStatus::Failed, .error = *next.failure});
        next_.reset();
        return;
    }
    const bool acknowledged = (statusword & cia402::kSetpointAcknowledge) != 0;
    switch (next.phase) {
    case Phase::Steps:
        if (!steps_done(next)) {
            return;
        }
        next.phase = Phase::Setpoint;
        [[fallthrough]];
    case Phase::Setpoint:
        if (!answered() || acknowledged) {
            return;
        }
        next.target = target_of(next.command, running_->target); // it starts where this ends
        last_target_ = next.target;
        link_.set_target_position(axis_, next.target);
        mode_bits_ = cia402::kNewSetpoint; // change set immediately clear: after this move
        next.phase = Phase::Acknowledge;
        return;
    case Phase::Acknowledge:
        if (answered() && acknowledged) {
            mode_bits_ = 0; // the drive keeps the acknowledge while the buffer is full
            next.phase = Phase::Moving;
        }
        return;
    case Phase::Moving:
        return;
    }
}

void AxisDriver::advance(std::uint16_t statusword) {
    Running& running = *running_;
    using K = MotionCommand::Kind;
    using Phase = Running::Phase;
    if (running.failure) {
        finish(CommandStatus::Failed, *running.failure);
        return;
    }
    const K kind = running.command.kind;
    switch (running.phase) {
    case Phase::Steps:
        if (!steps_done(running)) {
            return;
        }
        running.phase = Phase::Setpoint;
        [[fallthrough]];
    case Phase::Setpoint:
        if (is_position_move(kind)) {
            // The drive takes a new set-point once it has seen the last one's edge fall. Its
            // acknowledge may stay high meanwhile (a full set-point buffer): "change set
            // immediately" replaces what is buffered anyway.
            if (!answered()) {
                return;
            }
            running.target = target_of(running.command, link_.actual_position(axis_));
            last_target_ = running.target;
            link_.set_target_position(axis_, running.target);
            mode_bits_ = cia402::kNewSetpoint | cia402::kChangeImmediately;
            running.phase = Phase::Acknowledge;
            return;
        }
        last_target_.reset();
        mode_bits_ = kind == K::MoveVelocity ? 0
                     : kind == K::Home       ? cia402::kNewSetpoint
                                             : cia402::kHalt;
        // These set-points went by SDO (0x60FF, 0x6084), and the controlword may not change
        // (MoveVelocity, Halt after Halt): only a statusword two samples on speaks of them, e.g.
        // bit 10 "target velocity reached" of the new velocity (FW spec table 5-54).
        changed_at_ = link_.samples(axis_);
        running.phase = Phase::Moving;
        return;
    case Phase::Acknowledge:
        if (answered() && (statusword & cia402::kSetpointAcknowledge) != 0) {
            mode_bits_ = cia402::kChangeImmediately;
            running.phase = Phase::Moving;
        }
        return;
    case Phase::Moving:
        if (is_position_move(kind)) {
            hand_on(statusword);
            if (next_ && next_->phase != Phase::Steps && next_->phase != Phase::Setpoint) {
                // The next move is with the drive: this one ended when the drive took that
                // one out of its buffer (the acknowledge fell), not at a target reached.
                if (next_->phase == Phase::Moving && answered() &&
                    (statusword & cia402::kSetpointAcknowledge) == 0) {
                    finish(CommandStatus::Done);
                }
                return;
            }
        }
        if (!answered()) {
            return;
        }
        if (kind == K::MoveVelocity) {
            running.in_velocity = (statusword & cia402::kTargetReached) != 0;
            if (running.in_velocity && !waiting_.empty()) {
                finish(CommandStatus::Aborted); // a buffered command takes over at velocity
            }
            return;
        }
        if (kind == K::Home && (statusword & cia402::kHomingError) != 0) {
            finish(CommandStatus::Failed, ErrorId::HomingError);
            return;
        }
        const std::uint16_t reached = kind == K::Home
                                          ? cia402::kTargetReached | cia402::kHomingAttained
                                          : cia402::kTargetReached;
        if ((statusword & reached) == reached) {
            finish(CommandStatus::Done);
        }
        return;
    }
}

void AxisDriver::finish(CommandStatus status, ErrorId error) {
    const bool stop = running_->command.kind == MotionCommand::Kind::Stop;
    record(running_->id, {.status = status, .error = error});
    running_.reset();
    if (stop && !stop_released_) {
        return; // Stopping until its Execute falls
    }
    stop_ = 0;
    if (next_) {
        running_ = std::move(next_); // already with the drive, or on its way there
        return;
    }
    if (!waiting_.empty()) {
        const auto [id, command] = waiting_.front();
        waiting_.pop_front();
        start(id, command);
        return;
    }
    state_ = AxisState::Standstill;
}

void AxisDriver::release_stop(CommandId id) {
    if (id == 0 || id != stop_) {
        return;
    }
    if (running_ && running_->id == id) {
        stop_released_ = true;
        return;
    }
    stop_ = 0;
    state_ = AxisState::Standstill;
}

void AxisDriver::abort_all(CommandStatus status, ErrorId error) {
    for (std::unique_ptr<Running>* running : {&running_, &next_}) {
        if (*running) {
            record((*running)->id, {.status = status, .error = error});
            running->reset();
        }
    }
    for (const auto& [id, command] : waiting_) {
        record(id, {.status = status, .error = error});
    }
    waiting_.clear();
    stop_ = 0;
}

void AxisDriver::record(CommandId id, CommandReport report) {
    finished_.emplace_back(id, report);
    if (finished_.size() > kRememberedOutcomes) {
        finished_.pop_front();
    }
}

CommandReport AxisDriver::report(CommandId id) const {
    if (id != 0 && id == reset_) {
        return {.status = CommandStatus::Active};
    }
    if (running_ && running_->id == id) {
        return {.status = CommandStatus::Active, .in_velocity = running_->in_velocity};
    }
    if (next_ && next_->id == id) {
        return {.status = CommandStatus::Buffered};
    }
    for (const auto& [waiting, command] : waiting_) {
        if (waiting == id) {
            return {.status = CommandStatus::Buffered};
        }
    }
    const auto it = std::find_if(finished_.rbegin(), finished_.rend(),
                                 [id](const auto& entry) { return entry.first == id; });
    return it == finished_.rend() ? CommandReport{} : it->second;
}

Submitted AxisDriver::reset() {
    poll();
    const CommandId id = (static_cast<CommandId>(axis_) << 24) | (next_id_++ & 0xFFFFFF);
    if (state_ != AxisState::ErrorStop) {
        record(id, {.status = CommandStatus::Done});
        return {.id = id};
    }
    if (reset_ != 0) {
        record(reset_, {.status = CommandStatus::Aborted});
    }
    reset_ = id;
    reset_pulsed_ = false;
    poll();
    return {.id = id};
}

void AxisDriver::advance_reset(std::uint16_t statusword) {
    if (reset_ == 0) {
        return;
    }
    if (link_.presence(axis_) != AxisPresence::Ready) {
        record(std::exchange(reset_, 0),
               {.status = CommandStatus::Failed, .error = ErrorId::CommunicationLost});
        return;
    }
    if (cia402::is_fault_reaction_active(statusword)) {
        // FW spec 3.2.2, table 3-5: the reaction ends in Fault (14, 18), and only there does a
        // fault reset act (15); an edge given now would be lost.
        return;
    }
    if (!reset_pulsed_ && cia402::is_fault(statusword)) {
        device_bits_ = cia402::kFaultReset; // a rising edge of bit 7
        reset_pulsed_ = true;
        return;
    }
    if (!answered()) {
        return;
    }
    if (cia402::is_fault(statusword)) {
        record(std::exchange(reset_, 0),
               {.status = CommandStatus::Failed, .error = ErrorId::ResetFailed});
        device_bits_ = cia402::kQuickStop;
        return;
    }
    record(std::exchange(reset_, 0), {.status = CommandStatus::Done});
    state_ = AxisState::Disabled;
    axis_error_ = ErrorId::None;
    device_bits_ = cia402::kShutdown;
}

void AxisDriver::send_controlword() {
    const std::uint16_t controlword = device_bits_ | mode_bits_;
    if (sent_ == controlword) {
        return;
    }
    sent_ = controlword;
    link_.set_controlword(axis_, controlword);
    changed_at_ = link_.samples(axis_);
}

} // namespace eposp::plcopen
