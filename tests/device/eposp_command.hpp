#pragma once

#include "eposp/test/run_command.hpp"
#include "eposp/test/test_directory.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace eposp::device {

inline const std::string kEposp = EPOSP_EXECUTABLE;

/// Runs `eposp ARGUMENTS` as a user would in a shell; the output holds stdout and stderr.
inline test::CommandResult eposp(const std::string& arguments) {
    return test::run_command(kEposp + " " + arguments + " 2>&1");
}

/// A path for file `name` in a directory of the running test's own.
inline std::filesystem::path scratch(const std::string& name) {
    return test::test_file(name);
}

/// Writes `text` to file `name` of the test's own directory; returns its path.
inline std::string write_source(const std::string& name, const std::string& text) {
    const auto path = scratch(name);
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

inline std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Runs `eposp ARGUMENTS` in the background, sends it SIGINT (as Ctrl-C does) once it catches
/// the signal (the SigCgt mask of /proc/PID/status: its run has begun; up to 30 s on a loaded
/// machine), and returns its exit code and output.
inline test::CommandResult eposp_interrupted(const std::string& arguments,
                                             const std::filesystem::path& out) {
    return test::run_command(
        kEposp + " " + arguments + " > " + out.string() +
        " 2>&1 & pid=$!; for i in $(seq 600); do mask=$(sed -n 's/^SigCgt:\t*//p' "
        "/proc/$pid/status); "
        "[ -n \"$mask\" ] && [ $(( 0x$mask & 2 )) -ne 0 ] && break; sleep 0.05; done; "
        "kill -INT $pid; wait $pid; code=$?; cat " +
        out.string() + "; exit $code");
}

/// Runs `clients` (shell commands using $port) while `eposp ARGUMENTS` runs in the background
/// and serves the link whose path it prints after `printed: ` (waited for up to 30 s on a loaded
/// machine), then ends it with SIGINT. The output holds the clients' output, then the served
/// command's after a line "--- eposp <command>:"; the exit code is the clients'.
inline test::CommandResult with_served_port(const std::string& arguments,
                                            const std::string& printed, const std::string& clients,
                                            const std::filesystem::path& out) {
    const std::string start =
        ": > " + out.string() + "; " + kEposp + " " + arguments + " > " + out.string() +
        " 2>&1 & pid=$!; for i in $(seq 600); do port=$(sed -n \"s/^" + printed + ": //p\" " +
        out.string() + "); [ -n \"$port\" ] && break; sleep 0.05; done; ";
    auto result = test::run_command("sh -c '" + start + "{ " + clients +
                                    "; } 2>&1; code=$?; kill -INT $pid; wait $pid; exit $code'");
    result.output +=
        "\n--- eposp " + arguments.substr(0, arguments.find(' ')) + ":\n" + read_file(out);
    return result;
}

/// A shell-script prefix that starts `eposp ARGUMENTS` (which must serve socketcand, e.g.
/// `bus --socketcand 127.0.0.1:0`) in the background with its output in `out`, waits until it
/// listens (up to 30 s: a loaded CI machine starts it slowly), and leaves its address in
/// $address and its pid in $pid.
inline std::string start_in_background(const std::filesystem::path& out,
                                       const std::string& arguments) {
    // The file is emptied before the command starts in the background: otherwise the wait could
    // read the address a previous run left in it before the new process has truncated it.
    return ": > " + out.string() + "; " + kEposp + " " + arguments + " > " + out.string() +
           " & pid=$!; for i in $(seq 600); do address=$(sed -n \"s/^socketcand: listening on "
           "\\([^ ]*\\).*/\\1/p\" " +
           out.string() + "); [ -n \"$address\" ] && break; sleep 0.05; done; ";
}

} // namespace eposp::device
