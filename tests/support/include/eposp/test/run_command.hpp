#pragma once

#include <string>

namespace eposp::test {

struct CommandResult {
    int exit_code = -1;
    std::string output; ///< stdout and stderr, interleaved as written
};

/// Runs `command` through /bin/sh, the way a user types it, and waits for it.
CommandResult run_command(const std::string& command);

} // namespace eposp::test
