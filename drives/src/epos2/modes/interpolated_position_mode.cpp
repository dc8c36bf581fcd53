#include "interpolated_position_mode.hpp"

#include "eposp/drives/motion/device_error_codes.hpp"
#include "eposp/drives/motion/statusword_bits.hpp"

#include <cmath>

namespace eposp::drives::epos2 {

namespace {

constexpr std::uint16_t kEnableIpModeBit = 1U << 4;              // table 5-33
constexpr std::uint16_t kIpModeActiveBit = 1U << 12;             // table 8-114
constexpr std::uint16_t kInterpolatedPositionModeError = 0xFF0C; // 4.2.33

} // namespace

InterpolatedPositionMode::InterpolatedPositionMode(ModeServices& services) : services_(services) {}

void InterpolatedPositionMode::start(double, std::int64_t position, bool) {
    buffer_.clear();
    active_ = false;
    segment_.reset();
    halt_.reset();
    last_demand_ = {.position = static_cast<double>(position)};
    target_reached_ =
        motion::TargetReachedMonitor({services_.objects.get_as<std::uint32_t>(0x6067, 0),
                                      services_.objects.get_as<std::uint16_t>(0x6068, 0)});
    show_buffer();
}

void InterpolatedPositionMode::on_controlword(const ControlwordChange& change) {
    if ((change.rising & kHaltBit) != 0 && change.enabled) {
        // Table 5-33: halt stops the axis with the profile deceleration; the interpolation ends.
        const motion::ProfileParameters profile = services_.profile_parameters();
        halt_ = motion::Trajectory(
            last_demand_.position,
            {motion::make_ramp(last_demand_.velocity, 0, profile.deceleration, profile.shape)});
        halt_start_ = change.now;
        active_ = false;
        segment_.reset();
    }
    const bool halted = (change.controlword & kHaltBit) != 0;
    if ((change.rising & kEnableIpModeBit) != 0 && change.enabled && !halted) {
        activate(change.now);
    }
    if ((change.falling & kEnableIpModeBit) != 0) {
        active_ = false; // transition IV: the axis stays at the present demand
        segment_.reset();
    }
    show_buffer();
}

void InterpolatedPositionMode::on_set_value_written(double, std::uint16_t index,
                                                    std::uint8_t sub_index) {
    if (index == 0x20C1) {
        const auto record = decode_pvt_record(services_.objects.get_as<std::uint64_t>(0x20C1, 0));
        if (!buffer_.push(record) && active_) {
            abort(ipm_status::kOverflowError);
        }
    } else if (index == 0x60C4 && sub_index == 6) {
        // Buffer Clear: 0 clears the buffer and denies access, 1 enables it.
        if (services_.objects.get_as<std::uint8_t>(0x60C4, 6) == 0) {
            buffer_.clear();
        } else {
            buffer_.enable();
        }
    } else {
        return; // the sizes show_buffer() itself sets
    }
    show_buffer();
}

void InterpolatedPositionMode::activate(double now) {
    halt_.reset();
    active_ = true;
    last_demand_.velocity = 0; // the axis is at rest in the inactive state
    last_demand_.acceleration = 0;
    segment_start_ = now;
    next_segment(now);
}

void InterpolatedPositionMode::next_segment(double now) {
    const std::optional<PvtRecord> end = buffer_.pop();
    if (end && end->time_ms == 0) {
        active_ = false; // 8.2.69: time 0 ends the motion without error
        segment_.reset();
        last_demand_.velocity = 0;
        last_demand_.acceleration = 0;
        return;
    }
    // 8.2.69: while active, the FIFO holds the segment's end point and at least one more.
    if (!end || buffer_.size() < 1) {
        abort(ipm_status::kUnderflowError);
        return;
    }
    segment_.emplace(last_demand_.position, last_demand_.velocity,
                     static_cast<double>(end->position),
                     services_.velocity_to_counts(end->velocity), end->time_ms / 1000.0);
    segment_start_ = now;
}

void InterpolatedPositionMode::abort(std::uint16_t error_flag) {
    buffer_.flag(error_flag);
    active_ = false;
    segment_.reset();
    services_.raise_device_error(kInterpolatedPositionModeError);
}

ModeDemand InterpolatedPositionMode::demand(const ModeInputs& inputs) {
    if (halt_) {
        const motion::MotionState ramp = halt_->sample(inputs.now - halt_start_);
        last_demand_ = {.position = ramp.position,
                        .velocity = ramp.velocity,
                        .acceleration = ramp.acceleration};
        return {.motion = last_demand_};
    }
    while (active_ && segment_ && inputs.now - segment_start_ >= segment_->duration()) {
        last_demand_ = segment_->at(segment_->duration());
        next_segment(segment_start_ + segment_->duration());
    }
    if (active_ && segment_) {
        last_demand_ = segment_->at(inputs.now - segment_start_);
        check_limits(last_demand_);
    } else {
        last_demand_.velocity = 0;
        last_demand_.acceleration = 0;
    }
    return {.motion = last_demand_};
}

void InterpolatedPositionMode::check_limits(const motion::MotionState& state) {
    // Velocities in velocity units (0x6081, 0x607F), accelerations in rpm/s (0x6083, 0x60C5).
    const double velocity = std::abs(services_.counts_to_velocity(state.velocity));
    const double acceleration = std::abs(services_.counts_to_rpm(state.acceleration));
    const auto& od = services_.objects;
    if (velocity > od.get_as<std::uint32_t>(0x6081, 0)) {
        buffer_.flag(ipm_status::kVelocityWarning);
    }
    if (acceleration > od.get_as<std::uint32_t>(0x6083, 0)) {
        buffer_.flag(ipm_status::kAccelerationWarning);
    }
    if (velocity > od.get_as<std::uint32_t>(0x607F, 0)) {
        abort(ipm_status::kVelocityError);
    } else if (acceleration > od.get_as<std::uint32_t>(0x60C5, 0)) {
        abort(ipm_status::kAccelerationError);
    }
}

void InterpolatedPositionMode::watch(const ModeInputs& inputs, const motion::MotionState& demand) {
    const bool halt_ended = halt_ && inputs.now - halt_start_ >= halt_->duration();
    target_reached_now_ =
        target_reached_.update(inputs.now, !active_ && (!halt_ || halt_ended),
                               static_cast<double>(inputs.position), demand.position);
    show_buffer();
}

std::uint16_t InterpolatedPositionMode::statusword_bits(double, bool) const {
    std::uint16_t bits = 0;
    if (target_reached_now_) {
        bits |= motion::kTargetReachedBit;
    }
    if (active_) {
        bits |= kIpModeActiveBit;
    }
    return bits;
}

void InterpolatedPositionMode::drive_disabled(double) {
    active_ = false;
    segment_.reset();
    halt_.reset();
}

void InterpolatedPositionMode::stop_completed(double position) {
    active_ = false;
    segment_.reset();
    halt_.reset();
    last_demand_ = {.position = position};
    target_reached_.reset();
}

void InterpolatedPositionMode::show_buffer() {
    canopen::ObjectDictionary& od = services_.outputs;
    const std::uint16_t status = buffer_.status(od.get_as<std::uint16_t>(0x20C4, 2),
                                                od.get_as<std::uint16_t>(0x20C4, 3), active_);
    od.set_as(0x20C4, 1, status);
    const auto queued = static_cast<std::uint32_t>(buffer_.size());
    od.set_as(0x60C4, 2,
              buffer_.enabled()
                  ? static_cast<std::uint32_t>(InterpolationBuffer::kCapacity) - queued
                  : std::uint32_t{0});
    od.set_as(0x60C4, 4, static_cast<std::uint16_t>(queued));
}

} // namespace eposp::drives::epos2
