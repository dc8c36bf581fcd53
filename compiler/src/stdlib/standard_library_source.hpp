#pragma once

#include <string_view>

namespace eposp::compiler::stdlib {

/// The standard function blocks of IEC 61131-3 ed. 3, 6.6.3.5 (bistables, edge detection,
/// counters, timers, RTC) written in ST and compiled with every program. A FUNCTION without
/// statements in it is a host function imported by its name (the timers' clock).
std::string_view standard_library_source();

} // namespace eposp::compiler::stdlib
