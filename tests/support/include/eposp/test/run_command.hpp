#pragma once

#include <string>
#include <vector>

namespace eposp::test {

struct CommandResult {
    int exit_code = -1; ///< -1 when the command did not exit normally
    std::string output; ///< what it wrote to stdout (add `2>&1` to the command for stderr too)

    std::vector<std::string> lines() const;
};

/// Runs `command` through /bin/sh, the way a user types it, and waits for it; XDG_STATE_HOME
/// is a directory of the test's own (test_directory.hpp), so that no command writes to the
/// user's state directory.
CommandResult run_command(const std::string& command);

} // namespace eposp::test
