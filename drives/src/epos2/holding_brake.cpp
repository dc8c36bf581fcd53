#include "eposp/drives/epos2/holding_brake.hpp"

namespace eposp::drives::epos2 {
namespace {

constexpr std::uint16_t kNoBrakeTimeout = 65535; // 8.2.72 sub 3
// Control periods are whole microseconds; their times in seconds are doubles.
constexpr double kTimeTolerance = 1e-9;

bool elapsed(double now, double since, std::uint16_t ms) {
    return now - since >= ms * 1e-3 - kTimeTolerance;
}

} // namespace

void HoldingBrake::configure(bool present, HoldingBrakeTiming timing,
                             motion::StandstillWindow window) {
    present_ = present;
    timing_ = timing;
    standstill_ = motion::StandstillMonitor(window);
}

void HoldingBrake::enter(Phase phase, double now) {
    phase_ = phase;
    changed_ = now;
}

bool HoldingBrake::power_stage(double now, bool requested, bool fault, double velocity_averaged) {
    if (!present_) {
        // The standstill is read only with a brake, and configure(), which alone brings one,
        // starts a new monitor: without a brake there is nothing to watch.
        phase_ = requested ? Phase::Released : Phase::Off;
        return requested;
    }
    // 8.2.73: with the window off (65535), standstill is the end of the trajectory, which a
    // power stage no longer asked for has reached.
    const bool standstill = standstill_.update(now, velocity_averaged, !requested);
    switch (phase_) {
    case Phase::Off:
    case Phase::Coasting:
        if (requested) {
            enter(Phase::Released, now);
        } else if (phase_ == Phase::Coasting &&
                   (standstill || (timing_.timeout != kNoBrakeTimeout &&
                                   elapsed(now, changed_, timing_.timeout)))) {
            enter(Phase::Off, now);
        }
        break;
    case Phase::Released:
        if (!requested) {
            enter(!standstill ? Phase::Coasting : fault ? Phase::Off : Phase::Engaging, now);
        }
        break;
    case Phase::Engaging:
        if (requested) {
            enter(Phase::Released, now);
        } else if (fault || elapsed(now, changed_, timing_.rise_time)) {
            enter(Phase::Off, now);
        }
        break;
    }
    return phase_ == Phase::Released || phase_ == Phase::Engaging;
}

bool HoldingBrake::operation_may_start(double now) const {
    return !present_ || (phase_ == Phase::Released && elapsed(now, changed_, timing_.fall_time));
}

} // namespace eposp::drives::epos2
