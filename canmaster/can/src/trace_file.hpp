#pragma once

#include "eposp/core/result.hpp"

#include <filesystem>
#include <fstream>
#include <string_view>

// Internal: opening trace files with errors that say which file and why.
namespace eposp::can {

/// `cannot <verb> <path>: <reason from errno>`, for a stream that just failed to open.
core::Error file_error(std::string_view verb, const std::filesystem::path& path);

/// Opens `path` for reading in binary mode.
core::Result<std::ifstream> open_trace_file(const std::filesystem::path& path);

} // namespace eposp::can
