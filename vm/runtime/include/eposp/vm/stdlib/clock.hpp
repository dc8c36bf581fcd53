#pragma once

#include "eposp/vm/native.hpp"

#include <cstdint>
#include <functional>

namespace eposp::vm::stdlib {

/// Registers the clock the timers of the standard library read (clock_binding in
/// vm/stdlib/manifest.hpp) reading `now_ns`. The host supplies the clock, so a simulated run
/// uses the event loop's virtual time and every run is reproducible.
void register_clock(NativeRegistry& registry, std::function<std::int64_t()> now_ns);

} // namespace eposp::vm::stdlib
