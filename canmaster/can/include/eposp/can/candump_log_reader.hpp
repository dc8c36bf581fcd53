#pragma once

#include "eposp/can/candump_format.hpp"
#include "eposp/core/result.hpp"

#include <filesystem>
#include <istream>
#include <string_view>
#include <vector>

namespace eposp::can {

/// Reads a whole `candump -L` log. As for canplayer, a line that does not start with '(' is a
/// comment (candump itself writes `DROPCOUNT:` lines into logs); every other line must parse.
/// An error reads `<source_name>:<line>: <what is wrong>`.
core::Result<std::vector<CandumpRecord>> read_candump_log(std::istream& in,
                                                          std::string_view source_name);

/// As above from a file; errors name the file.
core::Result<std::vector<CandumpRecord>> read_candump_log_file(const std::filesystem::path& path);

} // namespace eposp::can
