#pragma once

#include "eposp/core/time.hpp"

#include <chrono>

namespace eposp::can {

/// A timestamp as candump logs and pcap files record it: time since the Unix epoch.
using TraceTime = std::chrono::sys_time<core::Duration>;

/// Turns the loop's clock into trace timestamps: loop time plus a fixed epoch offset. The one
/// place both trace writers take their timestamps from. A virtual run keeps the offset 0, so its
/// trace starts at 0 s; a real-time run uses aligned(), so its trace shows wall-clock epoch times
/// as candump's does.
class TraceClock {
public:
    TraceClock() = default;
    explicit TraceClock(core::Duration epoch_offset) : epoch_offset_(epoch_offset) {}

    /// The clock under which the loop time `loop_now` reads as `wall_now`. The caller reads the
    /// wall clock (components never do), e.g. `std::chrono::system_clock::now()`.
    static TraceClock aligned(core::TimePoint loop_now, TraceTime wall_now);

    TraceTime to_trace(core::TimePoint loop_time) const;
    core::Duration epoch_offset() const { return epoch_offset_; }

private:
    core::Duration epoch_offset_{};
};

} // namespace eposp::can
