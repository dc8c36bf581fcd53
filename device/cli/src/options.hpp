#pragma once

#include "eposp/core/time.hpp"
#include "eposp/device/hosted_bus.hpp"
#include "eposp/vm/program.hpp"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace eposp::device::cli {

/// Adds `--for DURATION` (`10s`, `250ms`, `2m`, ...), the bound every long-running command takes.
CLI::Option* add_duration_option(CLI::App& command, const std::string& name,
                                 std::optional<core::Duration>& target,
                                 const std::string& description);

/// Adds `--engine compiled|interpreter`: what runs the program (the interpreter is the reference,
/// compiled code the fast one; both give the same results).
CLI::Option* add_engine_option(CLI::App& command, vm::Engine& target);

/// Accepts a whole number from `lowest` to `highest`; the message names the range in digits
/// (CLI11's own ranges of doubles print hundreds of them).
CLI::Validator whole_number_in(std::uint64_t lowest, std::uint64_t highest);

/// Reports a user-facing failure as `eposp <command>: error: <message>` on stderr, or as
/// `eposp <command>: <message>` when the message names its file and says "error:" itself, and
/// returns the exit code for it, 1.
int report_user_error(std::string_view command, std::string_view message);

/// Adds the hosting options (--socketcand, --socketcan, --name, --bitrate, --log, --pcap, --for,
/// --virtual, --force) to `command`.
void add_hosted_bus_options(CLI::App& command, HostedBusOptions& options);

/// Why the traces of the hosting options must not be written (file_checks.hpp), given the
/// files the command reads.
std::optional<std::string> hosted_bus_outputs_problem(const HostedBusOptions& options,
                                                      std::span<const std::string> inputs);

} // namespace eposp::device::cli
