#pragma once

#include "eposp/core/result.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::device::cli {

/// The file that holds a simulated device's stored parameters (0x1010 store, 0x1011 restore;
/// LSS store configuration writes "<it>.lss" beside it): parameters.bin in its state directory,
/// which is `state_dir` when given, else `$XDG_STATE_HOME/eposp/<device>` or, without that
/// variable (or with a relative one, XDG Base Directory Specification 0.8),
/// `$HOME/.local/state/eposp/<device>`. The directory is created; an error says why it cannot be.
core::Result<std::string> stored_parameters_file(const std::optional<std::string>& state_dir,
                                                 std::string_view device);

/// The file that holds the EPOS P's downloaded program (0x1F50, CiA 302-3): program.epx in the
/// state directory of `stored_parameters_file`, which is created.
core::Result<std::string> stored_program_file(const std::optional<std::string>& state_dir,
                                              std::string_view device);

/// The file that holds the EPOS P's RETAIN variables between power cycles (the retain store):
/// retain.bin in the state directory of `stored_parameters_file`, which is created.
core::Result<std::string> stored_retain_file(const std::optional<std::string>& state_dir,
                                             std::string_view device);

/// Adds `--state-dir DIR`, naming the default `device` gets.
void add_state_dir_option(CLI::App& command, std::optional<std::string>& state_dir,
                          std::string_view device);

} // namespace eposp::device::cli
