#include "profile_velocity_mode.hpp"

#include "eposp/drives/motion/statusword_bits.hpp"

namespace eposp::drives::epos2 {

void ProfileVelocityMode::start(double now, std::int64_t position, bool power_stage_on) {
    profile_.reset(static_cast<double>(position));
    if (power_stage_on) {
        follow_target(now);
    }
    target_reached_ =
        motion::TargetReachedMonitor({services_.objects.get_as<std::uint32_t>(0x606D, 0),
                                      services_.objects.get_as<std::uint16_t>(0x606E, 0)});
}

void ProfileVelocityMode::follow_target(double now) {
    profile_.set_target(
        now, services_.velocity_to_counts(services_.objects.get_as<std::int32_t>(0x60FF, 0)),
        services_.profile_parameters());
}

void ProfileVelocityMode::on_controlword(const ControlwordChange& change) {
    if (((change.rising | change.falling) & kHaltBit) != 0) {
        profile_.set_halt(change.now, (change.controlword & kHaltBit) != 0);
    }
}

void ProfileVelocityMode::on_set_value_written(double now, std::uint16_t index, std::uint8_t) {
    if (index == 0x60FF) {
        follow_target(now);
    }
}

ModeDemand ProfileVelocityMode::demand(const ModeInputs& inputs) {
    return {.motion = profile_.update(inputs.now)};
}

void ProfileVelocityMode::watch(const ModeInputs& inputs, const motion::MotionState& demand) {
    // The window 0x606D and the target in velocity units, the standstill window 0x2101 in rpm.
    const double velocity = services_.counts_to_velocity(inputs.velocity);
    const double target = (inputs.controlword & kHaltBit) != 0
                              ? 0.0
                              : services_.objects.get_as<std::int32_t>(0x60FF, 0);
    target_reached_now_ =
        target_reached_.update(inputs.now, profile_.ramp_finished(inputs.now), velocity, target);
    standstill_now_ = services_.standstill.update(
        inputs.now, services_.counts_to_rpm(inputs.velocity), demand.velocity == 0);
}

// Table 8-114, 5.10.2.5.
std::uint16_t ProfileVelocityMode::statusword_bits(double, bool) const {
    std::uint16_t bits = 0;
    if (target_reached_now_)
        bits |= motion::kTargetReachedBit;
    if (standstill_now_)
        bits |= motion::kSpeedZeroBit;
    return bits;
}

} // namespace eposp::drives::epos2
