#include "eposp/drives/epos2/position_marker.hpp"

namespace eposp::drives::epos2 {

void PositionMarker::configure(MarkerEdge edge, MarkerMode mode) {
    edge_ = edge;
    mode_ = mode;
}

bool PositionMarker::capturing() const {
    switch (mode_) {
    case MarkerMode::Continuous:
        return true;
    case MarkerMode::Multiple:
        return counter_ < positions_.size();
    case MarkerMode::Single:
    case MarkerMode::SingleAndStop:
        return counter_ == 0;
    }
    return false;
}

bool PositionMarker::update(bool state, bool executed, std::int32_t position) {
    const bool rising = state && !before_;
    const bool falling = !state && before_;
    before_ = state;
    const bool edge =
        (rising && edge_ != MarkerEdge::Falling) || (falling && edge_ != MarkerEdge::Rising);
    if (!edge || !executed || homing_ || !capturing()) {
        return false;
    }
    positions_[2] = positions_[1];
    positions_[1] = positions_[0];
    positions_[0] = position;
    ++counter_;
    return mode_ == MarkerMode::SingleAndStop;
}

void PositionMarker::homing_started() {
    positions_ = {};
    counter_ = 0;
    homing_ = true;
}

void PositionMarker::counter_written(std::uint16_t counter) {
    counter_ = counter;
    if (counter == 0) {
        positions_ = {};
    }
}

} // namespace eposp::drives::epos2
