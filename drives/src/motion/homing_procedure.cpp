#include "eposp/drives/motion/homing_procedure.hpp"

#include "eposp/drives/motion/device_error_codes.hpp"
#include "eposp/drives/motion/profile_planner.hpp"
#include "eposp/drives/motion/statusword_bits.hpp"

#include <cmath>
#include <cstdlib>

namespace eposp::drives::motion {

namespace {

// The index search gives up where the EPOS2 gives up on the index at start-up (4.2.24).
constexpr std::int64_t kIndexSearchTurns = 2;

bool moves(const HomingMethodTraits& traits) {
    return traits.search_direction != 0;
}

bool valid(const HomingParameters& p, const HomingMethodTraits& traits) {
    // A threshold of zero would be crossed at standstill, before any end stop.
    const bool threshold_valid =
        traits.reference != HomingReference::CurrentThreshold || p.current_threshold > 0;
    return p.switch_search_speed > 0 && p.zero_search_speed > 0 && p.acceleration > 0 &&
           p.counts_per_turn > 0 && threshold_valid;
}

} // namespace

std::optional<std::uint16_t> error_code(HomingFailure failure) {
    switch (failure) {
    case HomingFailure::NegativeLimitSwitch:
        return kNegativeLimitSwitchErrorCode;
    case HomingFailure::PositiveLimitSwitch:
        return kPositiveLimitSwitchErrorCode;
    case HomingFailure::InvalidParameters:
    case HomingFailure::IndexNotFound:
    case HomingFailure::DriveDisabled:
        break;
    }
    return std::nullopt;
}

HomingProcedure::HomingProcedure(double position) {
    reset(position);
}

void HomingProcedure::reset(double position) {
    trajectory_ = Trajectory(position, {});
    trajectory_start_ = 0;
    phase_ = Phase::Idle;
    failure_.reset();
}

void HomingProcedure::start(double now, const HomingParameters& parameters,
                            const MotionState& from) {
    parameters_ = parameters;
    traits_ = traits(parameters.method);
    failure_.reset();
    // Until the first update plans the search, the axis holds still (or brakes if it moves).
    trajectory_ = Trajectory(from.position, {});
    trajectory_start_ = now;
    if (moves(traits_) && !valid(parameters, traits_)) {
        failure_ = HomingFailure::InvalidParameters;
        phase_ = Phase::Failed;
        return;
    }
    if (from.velocity != 0) {
        trajectory_ = plan_stop(from, parameters_.acceleration, parameters_.shape);
    }
    phase_ = halted_ ? Phase::Halted : Phase::Beginning;
}

bool HomingProcedure::in_progress() const {
    switch (phase_) {
    case Phase::Beginning:
    case Phase::SearchingReference:
    case Phase::LeavingSwitch:
    case Phase::SearchingIndex:
    case Phase::MovingToHome:
        return true;
    case Phase::Idle:
    case Phase::Halted:
    case Phase::Attained:
    case Phase::Failed:
        break;
    }
    return false;
}

void HomingProcedure::interrupt(double now) {
    if (started()) {
        stop(now, Phase::Idle);
    }
}

void HomingProcedure::set_halt(double now, bool halt) {
    if (halt == halted_) {
        return;
    }
    halted_ = halt;
    if (halt && in_progress()) {
        stop(now, Phase::Halted);
    } else if (!halt && phase_ == Phase::Halted) {
        phase_ = Phase::Beginning;
    }
}

void HomingProcedure::drive_disabled(double now) {
    if (started()) {
        trajectory_ = Trajectory(demand(now).position, {});
        trajectory_start_ = now;
        failure_ = HomingFailure::DriveDisabled;
        phase_ = Phase::Failed;
    }
}

HomingStep HomingProcedure::update(double now, const HomingInputs& sensed) {
    std::optional<std::int64_t> offset;
    switch (phase_) {
    case Phase::Beginning:
        offset = begin(now, sensed);
        break;
    case Phase::SearchingReference:
        search_reference(now, sensed);
        break;
    case Phase::LeavingSwitch:
        leave_switch(now, sensed);
        break;
    case Phase::SearchingIndex:
        search_index(now, sensed);
        break;
    case Phase::MovingToHome:
        offset = move_to_home(now, sensed);
        break;
    case Phase::Idle:
    case Phase::Halted:
    case Phase::Attained:
    case Phase::Failed:
        break;
    }
    previous_ = sensed;
    return {demand(now), offset};
}

std::optional<std::int64_t> HomingProcedure::begin(double now, const HomingInputs& sensed) {
    previous_ = sensed; // switches already active at the start are no new edges
    reversed_ = false;
    if (parameters_.method == HomingMethod::NoHoming) {
        complete(now, parameters_.home_position); // attained at once, nothing re-zeroed
        return std::nullopt;
    }
    if (parameters_.method == HomingMethod::ActualPosition) {
        // 5.4.3.10: the present position becomes the home position, without a move.
        return complete(now, sensed.position);
    }
    const int direction = traits_.search_direction;
    if (traits_.reference == HomingReference::None) {
        search_index_from(now, sensed.position, direction); // 5.4.3.9
    } else if (reference_switch_active(sensed)) {
        // Already on the switch (5.4.3.3: "except the home switch is already active"): leave it.
        leave_reference_switch(now);
    } else {
        direction_ = direction;
        move_at(now, direction_ * parameters_.switch_search_speed);
        phase_ = Phase::SearchingReference;
    }
    return std::nullopt;
}

void HomingProcedure::search_reference(double now, const HomingInputs& sensed) {
    if (traits_.reference == HomingReference::CurrentThreshold) {
        // 5.4.3.11-14: the end stop shows as the current pushing against it.
        if (sensed.current * direction_ >= parameters_.current_threshold) {
            if (traits_.uses_index) {
                search_index_from(now, sensed.position, -direction_);
            } else {
                start_home_move(now, sensed.position);
            }
            return;
        }
    } else if (reference_switch_active(sensed)) {
        leave_reference_switch(now);
        return;
    }
    if (traits_.reference == HomingReference::HomeSwitch && !reversed_ &&
        limit_switch_ahead(sensed)) {
        // CiA 402 methods 7…14: the home switch lies behind; search it the other way.
        reversed_ = true;
        direction_ = -direction_;
        move_at(now, direction_ * parameters_.switch_search_speed);
        return;
    }
    if (const auto hit = limit_switch_hit(sensed, traits_.reference)) {
        fail(now, *hit);
    }
}

void HomingProcedure::leave_switch(double now, const HomingInputs& sensed) {
    // While still braking from the search the axis may run through a short cam and out of it;
    // only the falling edge met on the way back counts.
    const bool leaving = demand(now).velocity * direction_ > 0;
    if (leaving && reference_switch_active(previous_) && !reference_switch_active(sensed)) {
        if (traits_.uses_index) {
            // An index latched in this very period may lie on either side of the edge; like a
            // real drive the search needs index and edge apart, and takes the next index.
            search_index_from(now, sensed.position, direction_);
        } else {
            start_home_move(now, sensed.position); // 5.4.3.5-8: the falling edge is home
        }
        return;
    }
    if (const auto hit = limit_switch_hit(sensed, traits_.reference)) {
        fail(now, *hit);
    }
}

void HomingProcedure::search_index(double now, const HomingInputs& sensed) {
    if (sensed.index_position) {
        start_home_move(now, *sensed.index_position);
        return;
    }
    if (std::abs(sensed.position - index_search_start_) >
        kIndexSearchTurns * parameters_.counts_per_turn) {
        fail(now, HomingFailure::IndexNotFound);
        return;
    }
    if (const auto hit = limit_switch_hit(sensed, traits_.reference)) {
        fail(now, *hit);
    }
}

std::optional<std::int64_t> HomingProcedure::move_to_home(double now, const HomingInputs& sensed) {
    // The home offset should keep the axis off its switches (8.2.104); none is expected now.
    if (const auto hit = limit_switch_hit(sensed, HomingReference::None)) {
        fail(now, *hit);
        return std::nullopt;
    }
    if (now < trajectory_start_ + trajectory_.duration()) {
        return std::nullopt;
    }
    return complete(now, home_point_);
}

void HomingProcedure::leave_reference_switch(double now) {
    // Back off the switch slowly: its falling edge, met at the zero search speed, is the sharp
    // one.
    direction_ = -traits_.search_direction;
    move_at(now, direction_ * parameters_.zero_search_speed);
    phase_ = Phase::LeavingSwitch;
}

void HomingProcedure::search_index_from(double now, std::int64_t position, int direction) {
    direction_ = direction;
    index_search_start_ = position;
    move_at(now, direction_ * parameters_.zero_search_speed);
    phase_ = Phase::SearchingIndex;
}

void HomingProcedure::move_at(double now, double velocity) {
    if (trajectory_.final_velocity() == velocity) {
        return; // already heading for that velocity (a trajectory cannot hold one forever twice)
    }
    const double a = parameters_.acceleration;
    trajectory_ =
        plan_velocity_change(demand(now), velocity, {std::abs(velocity), a, a, parameters_.shape});
    trajectory_start_ = now;
}

void HomingProcedure::start_home_move(double now, std::int64_t reference) {
    home_point_ = reference + parameters_.home_offset;
    const double a = parameters_.acceleration;
    trajectory_ = plan_position_move(demand(now), static_cast<double>(home_point_),
                                     {parameters_.switch_search_speed, a, a, parameters_.shape});
    trajectory_start_ = now;
    phase_ = Phase::MovingToHome;
}

std::int64_t HomingProcedure::complete(double now, std::int64_t home_point) {
    // 5.4.3.1 c): the point reached "is set to Home Position"; the demand moves with the counter.
    const std::int64_t offset = parameters_.home_position - home_point;
    trajectory_ = Trajectory(demand(now).position + static_cast<double>(offset), {});
    trajectory_start_ = now;
    phase_ = Phase::Attained;
    referenced_ = true;
    return offset;
}

void HomingProcedure::stop(double now, Phase next) {
    const MotionState from = demand(now);
    trajectory_ = parameters_.acceleration > 0
                      ? plan_stop(from, parameters_.acceleration, parameters_.shape)
                      : Trajectory(from.position, {});
    trajectory_start_ = now;
    phase_ = next;
}

void HomingProcedure::fail(double now, HomingFailure failure) {
    failure_ = failure;
    stop(now, Phase::Failed);
}

bool HomingProcedure::limit_switch_ahead(const HomingInputs& sensed) const {
    return direction_ < 0 ? sensed.negative_limit : direction_ > 0 && sensed.positive_limit;
}

std::optional<HomingFailure> HomingProcedure::limit_switch_hit(const HomingInputs& sensed,
                                                               HomingReference expected) const {
    // A limit switch counts when it lies ahead or has just become active (whatever the
    // direction: a miswired input); the switch a method searches is not an error.
    const bool negative = sensed.negative_limit && (direction_ < 0 || !previous_.negative_limit) &&
                          expected != HomingReference::NegativeLimitSwitch;
    const bool positive = sensed.positive_limit && (direction_ > 0 || !previous_.positive_limit) &&
                          expected != HomingReference::PositiveLimitSwitch;
    if (negative) {
        return HomingFailure::NegativeLimitSwitch;
    }
    if (positive) {
        return HomingFailure::PositiveLimitSwitch;
    }
    return std::nullopt;
}

bool HomingProcedure::reference_switch_active(const HomingInputs& sensed) const {
    switch (traits_.reference) {
    case HomingReference::NegativeLimitSwitch:
        return sensed.negative_limit;
    case HomingReference::PositiveLimitSwitch:
        return sensed.positive_limit;
    case HomingReference::HomeSwitch:
        return sensed.home_switch;
    case HomingReference::None:
    case HomingReference::CurrentThreshold:
        break;
    }
    return false;
}

bool HomingProcedure::at_rest(double now) const {
    return now >= trajectory_start_ + trajectory_.duration() && trajectory_.final_velocity() == 0;
}

std::uint16_t HomingProcedure::statusword_bits(double now) const {
    const std::uint16_t reached = at_rest(now) ? kTargetReachedBit : 0;
    switch (phase_) {
    case Phase::Idle:
    case Phase::Halted:
        return reached; // CiA 402: "interrupted or not started"; halted: the axle stands
    case Phase::Attained:
        return kHomingAttainedBit | kTargetReachedBit;
    case Phase::Failed:
        return static_cast<std::uint16_t>(kHomingErrorBit | reached);
    case Phase::Beginning:
    case Phase::SearchingReference:
    case Phase::LeavingSwitch:
    case Phase::SearchingIndex:
    case Phase::MovingToHome:
        break;
    }
    return 0;
}

} // namespace eposp::drives::motion
