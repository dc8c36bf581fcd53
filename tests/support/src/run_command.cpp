#include "eposp/test/run_command.hpp"

#include "eposp/test/test_directory.hpp"

#include <array>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

namespace eposp::test {

std::vector<std::string> CommandResult::lines() const {
    std::vector<std::string> result;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) {
        result.push_back(line);
    }
    return result;
}

CommandResult run_command(const std::string& command) {
    // The simulated devices keep their non-volatile memory under $XDG_STATE_HOME: a test's own
    // directory, never the user's (for every command of the script: export).
    const std::string script =
        "export XDG_STATE_HOME='" + test_file("xdg-state").string() + "'; " + command;
    FILE* pipe = popen(script.c_str(), "r");
    if (pipe == nullptr) {
        throw std::runtime_error("cannot start: " + command);
    }
    CommandResult result;
    std::array<char, 4096> buffer{};
    while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) {
        result.output.append(buffer.data(), n);
    }
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

} // namespace eposp::test
