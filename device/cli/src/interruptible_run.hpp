#pragma once

#include "eposp/core/event_loop.hpp"

namespace eposp::device::cli {

/// Runs the virtual-time `loop` until `end` in slices of `slice`, and stops between two slices
/// when SIGINT or SIGTERM arrived (the signals are caught only meanwhile); true when stopped so.
/// Unlike device::run_until_done, the loop polls no I/O between its events, so `eposp bench`
/// times the program alone and `eposp run` runs at full speed.
bool run_until_interrupted(core::EventLoop& loop, core::TimePoint end, core::Duration slice);

} // namespace eposp::device::cli
