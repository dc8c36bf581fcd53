#include "eposp/drives/motion/software_position_limit.hpp"

#include "eposp/drives/motion/device_error_codes.hpp"

#include <algorithm>

namespace eposp::drives::motion {

namespace {

constexpr std::int32_t kMinimumOff = std::numeric_limits<std::int32_t>::min();
constexpr std::int32_t kMaximumOff = std::numeric_limits<std::int32_t>::max();

} // namespace

bool SoftwarePositionLimit::allows(double position) const {
    return (minimum == kMinimumOff || position >= minimum) &&
           (maximum == kMaximumOff || position <= maximum);
}

double SoftwarePositionLimit::clamp(double position) const {
    if (minimum != kMinimumOff) {
        position = std::max(position, static_cast<double>(minimum));
    }
    if (maximum != kMaximumOff) {
        position = std::min(position, static_cast<double>(maximum));
    }
    return position;
}

std::optional<std::uint16_t> SoftwarePositionLimit::check_target(double end_position) const {
    if (allows(end_position)) {
        return std::nullopt;
    }
    return kSoftwarePositionLimitErrorCode;
}

std::optional<std::uint16_t> SoftwarePositionLimitMonitor::update(double actual) {
    const bool was_active = active_;
    active_ = !limit_.allows(actual);
    if (active_ && !was_active) {
        return kSoftwarePositionLimitErrorCode;
    }
    return std::nullopt;
}

} // namespace eposp::drives::motion
