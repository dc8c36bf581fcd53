#pragma once

// Internal: the symlink a user names for a pseudo-terminal's slave (`--serial-link ./ttyEPOSP`).

#include "eposp/core/result.hpp"

#include <filesystem>

namespace eposp::service {

/// Makes `link` point to `slave`. A missing path is created; a symlink to a /dev/pts/N that no
/// longer exists (left by a run that did not close) is replaced; anything else is refused, so
/// that no file of the user's is ever overwritten.
core::Result<bool> make_pty_symlink(const std::filesystem::path& link,
                                    const std::filesystem::path& slave);

/// Removes `link` if it still points to `slave` (nobody replaced it meanwhile).
void remove_pty_symlink(const std::filesystem::path& link, const std::filesystem::path& slave);

} // namespace eposp::service
