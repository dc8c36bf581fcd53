#pragma once

namespace eposp::device {

/// Runs the `eposp` command line: parses `argv`, runs the subcommand and returns the process
/// exit code (0 success, 1 a user error reported on stderr).
int run_cli(int argc, char** argv);

} // namespace eposp::device
