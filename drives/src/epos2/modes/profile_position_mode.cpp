#include "profile_position_mode.hpp"

#include "eposp/drives/motion/software_position_limit.hpp"
#include "eposp/drives/motion/statusword_bits.hpp"

#include <cmath>

namespace eposp::drives::epos2 {
namespace {

// 4.2.11: "Target Position too high with Profile Velocity too low". The simulation's planner
// counts a move's time in control periods (1 ms) in a signed 32-bit number, as a firmware would:
// a move whose cruise, distance / profile velocity, lasts longer than (2^31 - 1) ms (24.9 days)
// cannot be planned. The spec gives no figure; this is the simulation's limit.
constexpr double kLongestMove = 2'147'483'647e-3; // s
constexpr std::uint16_t kSoftwareParameterErrorCode = 0x6320;

} // namespace

void ProfilePositionMode::start(double, std::int64_t position, bool) {
    profile_.reset(static_cast<double>(position));
    setpoint_acknowledged_ = false;
    target_reached_ =
        motion::TargetReachedMonitor({services_.objects.get_as<std::uint32_t>(0x6067, 0),
                                      services_.objects.get_as<std::uint16_t>(0x6068, 0)});
}

void ProfilePositionMode::on_controlword(const ControlwordChange& change) {
    if ((change.rising & kNewSetpointBit) != 0 && change.enabled) {
        setpoint_acknowledged_ = new_setpoint(change.now, change.controlword);
    }
    if ((change.falling & kNewSetpointBit) != 0) {
        setpoint_acknowledged_ = profile_.buffer_full();
    }
    if (((change.rising | change.falling) & kHaltBit) != 0) {
        profile_.set_halt(change.now, (change.controlword & kHaltBit) != 0);
    }
}

// 5.3.2.3: a new setpoint, unless the buffer is full or its end lies outside 0x607D (5.3.2.1).
bool ProfilePositionMode::new_setpoint(double now, std::uint16_t controlword) {
    const auto& od = services_.objects;
    motion::PositionSetpoint setpoint;
    setpoint.target = od.get_as<std::int32_t>(0x607A, 0);
    setpoint.relative = (controlword & kRelativeBit) != 0;
    setpoint.endless = (controlword & kEndlessMovementBit) != 0;
    setpoint.parameters = services_.profile_parameters();
    const motion::SoftwarePositionLimit limit{od.get_as<std::int32_t>(0x607D, 1),
                                              od.get_as<std::int32_t>(0x607D, 2)};
    const double end =
        setpoint.relative ? profile_.demand_target() + setpoint.target : setpoint.target;
    if (!setpoint.endless) {
        if (const auto error = limit.check_target(end)) {
            services_.raise_device_error(*error);
            return false;
        }
        if (std::abs(end - profile_.demand_target()) / setpoint.parameters.velocity >
            kLongestMove) {
            services_.raise_device_error(kSoftwareParameterErrorCode);
            return false;
        }
    }
    target_reached_.reset();
    return profile_.new_setpoint(now, setpoint, (controlword & kChangeImmediatelyBit) != 0);
}

ModeDemand ProfilePositionMode::demand(const ModeInputs& inputs) {
    return {.motion = profile_.update(inputs.now)};
}

void ProfilePositionMode::watch(const ModeInputs& inputs, const motion::MotionState&) {
    if ((inputs.controlword & kNewSetpointBit) == 0) {
        setpoint_acknowledged_ = profile_.buffer_full();
    }
    target_reached_now_ =
        target_reached_.update(inputs.now, profile_.finished(inputs.now),
                               static_cast<double>(inputs.position), profile_.demand_target());
}

// Table 8-114, 5.3.2.5.
std::uint16_t ProfilePositionMode::statusword_bits(double, bool following_error) const {
    std::uint16_t bits = 0;
    if (target_reached_now_)
        bits |= motion::kTargetReachedBit;
    if (setpoint_acknowledged_)
        bits |= motion::kSetpointAcknowledgeBit;
    if (following_error)
        bits |= motion::kFollowingErrorBit;
    return bits;
}

} // namespace eposp::drives::epos2
