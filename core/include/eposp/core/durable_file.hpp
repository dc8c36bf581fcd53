#pragma once

#include "eposp/core/result.hpp"

#include <filesystem>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace eposp::core {

/// Replaces `path` with `content` so that a crash or power loss leaves either the old or the
/// new file, never a mix: the bytes go to a temporary file beside it, which is fsync'ed and then
/// renamed over `path`, and the directory is fsync'ed so that the rename itself is durable.
/// Empty on success.
std::optional<Error> write_file_durably(const std::filesystem::path& path,
                                              std::span<const std::uint8_t> content);

/// Removes `path` durably (unlink, then fsync the directory); a missing file is no error.
std::optional<Error> remove_file_durably(const std::filesystem::path& path);

/// The whole file; nullopt when it does not exist.
Result<std::optional<std::vector<std::uint8_t>>> read_whole_file(const std::filesystem::path& path);

} // namespace eposp::core
