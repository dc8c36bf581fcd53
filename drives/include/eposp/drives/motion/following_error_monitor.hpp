#pragma once

#include <cstdint>
#include <optional>

namespace eposp::drives::motion {

/// The value of 0x6065 that switches the following control off (8.2.94: 2^32 − 1).
inline constexpr std::uint32_t kFollowingControlOff = 0xFFFFFFFF;

/// Maximal Following Error 0x6065 (EPOS2 FW spec 5.9.1.2, 8.2.94): a following error while the
/// position actual value is further from the position demand value than the maximum. The EPOS2
/// has no separate following error window or time-out (0x6066); this one object is both.
class FollowingErrorMonitor {
public:
    explicit FollowingErrorMonitor(std::uint32_t max_following_error = 2000) // the default
        : max_(max_following_error) {}

    /// Error 0x8611 (4.2.22) when the following error begins in this control period.
    std::optional<std::uint16_t> update(double demand, double actual);
    /// Statusword bit 13 in PPM (table 5-19).
    bool active() const { return active_; }

private:
    std::uint32_t max_;
    bool active_ = false;
};

} // namespace eposp::drives::motion
