#pragma once

#include "eposp/test/run_command.hpp"

#include <string>

namespace eposp::device {

inline const std::string kEposp = EPOSP_EXECUTABLE;

/// Runs `eposp ARGUMENTS` as a user would in a shell; the output holds stdout and stderr.
inline test::CommandResult eposp(const std::string& arguments) {
    return test::run_command(kEposp + " " + arguments + " 2>&1");
}

} // namespace eposp::device
