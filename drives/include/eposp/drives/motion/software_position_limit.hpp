#pragma once

#include <cstdint>
#include <limits>
#include <optional>

namespace eposp::drives::motion {

/// Software Position Limit 0x607D (EPOS2 FW spec 8.2.105); each extreme switches its check off.
struct SoftwarePositionLimit {
    std::int32_t minimum = std::numeric_limits<std::int32_t>::min(); ///< sub 1
    std::int32_t maximum = std::numeric_limits<std::int32_t>::max(); ///< sub 2

    /// Whether `position` lies within the limits that are switched on.
    bool allows(double position) const;
    /// The nearest position within the limits: Position Mode's limiter of its setting value (5.6).
    double clamp(double position) const;
    /// 5.3.2.1: "a new target position will be checked against these limits"; one outside is
    /// refused with error 0xFF09 (4.2.30), returned here. `end_position` is the absolute end of
    /// the move (for a relative target: position demand value + target).
    std::optional<std::uint16_t> check_target(double end_position) const;
};

/// The position actual value watched against the limits (8.2.105: "if the desired or the actual
/// position is lower than the negative position limit, a software position limit error will be
/// launched").
class SoftwarePositionLimitMonitor {
public:
    explicit SoftwarePositionLimitMonitor(SoftwarePositionLimit limit = {}) : limit_(limit) {}

    /// Error 0xFF09 when the actual position leaves the limits in this control period.
    std::optional<std::uint16_t> update(double actual);
    bool active() const { return active_; }

private:
    SoftwarePositionLimit limit_;
    bool active_ = false;
};

} // namespace eposp::drives::motion
