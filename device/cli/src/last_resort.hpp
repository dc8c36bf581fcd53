#pragma once

#include "exit_codes.hpp"

#include <cstdio>
#include <exception>
#include <fmt/format.h>

namespace eposp::device::cli {

/// Runs `command` (which returns the exit code); an exception that escapes it is reported as
/// `eposp: internal error: ...` and exits with kExitInternalError instead of aborting the
/// process (which would lose the message and, in a script, look like a crash of the device).
template <typename Command>
int with_last_resort_handler(Command&& command) noexcept {
    try {
        return command();
    } catch (const std::exception& error) {
        fmt::print(stderr, "eposp: internal error: {}\n", error.what());
    } catch (...) {
        fmt::print(stderr, "eposp: internal error: an exception that is not a std::exception\n");
    }
    return kExitInternalError;
}

} // namespace eposp::device::cli
