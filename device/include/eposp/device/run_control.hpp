#pragma once

#include "eposp/core/event_loop.hpp"

#include <optional>

namespace eposp::device {

/// How a long-running command ended.
enum class RunEnd {
    Elapsed,
    Interrupted,
    Idle,
    Lost, ///< the bus it joined went away (HostedBus)
};

/// Runs `loop` for `duration` (virtual or wall time, as the loop runs) or, without one, until
/// SIGINT or SIGTERM; a signal always ends the run cleanly after the current event. In virtual
/// pace a run without a duration also ends when no event is left.
RunEnd run_until_done(core::EventLoop& loop, std::optional<core::Duration> duration);

} // namespace eposp::device
