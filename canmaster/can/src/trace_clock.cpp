#include "eposp/can/trace_clock.hpp"

namespace eposp::can {

TraceClock TraceClock::aligned(core::TimePoint loop_now, TraceTime wall_now) {
    return TraceClock(wall_now.time_since_epoch() - loop_now.time_since_epoch());
}

TraceTime TraceClock::to_trace(core::TimePoint loop_time) const {
    return TraceTime(loop_time.time_since_epoch() + epoch_offset_);
}

} // namespace eposp::can
