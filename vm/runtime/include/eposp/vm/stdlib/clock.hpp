#pragma once

#include "eposp/vm/native.hpp"

#include <cstdint>
#include <functional>
#include <string_view>

namespace eposp::vm::stdlib {

/// The native the timers of the standard library (TP, TON, TOF, IEC 61131-3 ed. 3, 6.6.3.5.5)
/// read the time from: () -> TIME, nanoseconds of a monotonic clock.
inline constexpr std::string_view kClockNative = "CURRENT_TIME";

/// Registers kClockNative reading `now_ns`. The host supplies the clock, so a simulated run
/// uses the event loop's virtual time and every run is reproducible.
void register_clock(NativeRegistry& registry, std::function<std::int64_t()> now_ns);

} // namespace eposp::vm::stdlib
