#pragma once

namespace eposp::device::cli {

// What the process exit code says (docs/architecture.md, "Exit codes"): scripts and CI tell a
// mistake in the command line from a program that ran into errors and from a bug in eposp.
inline constexpr int kExitSuccess = 0;
/// Bad arguments or files; the command did not do its job (a message says why).
inline constexpr int kExitUserError = 1;
/// An exception no command handled: a bug in eposp.
inline constexpr int kExitInternalError = 2;
/// The program ran, but the device raised errors (a task stopped, overruns 0x6183 / 0x6184, a
/// retain failure 0x6310, ...) or a trace could not be written.
inline constexpr int kExitDeviceErrors = 3;
/// Stopped by SIGINT (Ctrl-C) before its end, as shells report it (128 + 2).
inline constexpr int kExitInterrupted = 130;

} // namespace eposp::device::cli
