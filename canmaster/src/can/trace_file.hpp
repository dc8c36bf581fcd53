#pragma once

#include "eposp/canmaster/can/trace_result.hpp"

#include <filesystem>
#include <fstream>
#include <string_view>

// Internal: opening trace files with errors that say which file and why.
namespace eposp::can {

/// `cannot <verb> <path>: <reason from errno>`, for a stream that just failed to open.
TraceError file_error(std::string_view verb, const std::filesystem::path& path);

/// Opens `path` for reading in binary mode.
TraceResult<std::ifstream> open_trace_file(const std::filesystem::path& path);

} // namespace eposp::can
