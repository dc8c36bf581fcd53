#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/vm/plc_runtime.hpp"
#include "program_input.hpp"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::device::cli {

/// What `eposp run` and `eposp serve` share: the program, the network, the PLC's settings and
/// the traces to write.
struct SessionOptions {
    std::vector<std::string> paths; ///< one .epx image or the .st files of one program
    std::optional<std::string> network;
    std::vector<std::string> watch;
    std::uint64_t ns_per_instruction = 0;
    std::uint64_t watchdog = vm::RuntimeConfig{}.watchdog_instructions;
    std::optional<std::string> retain_file;
    std::string start = "cold";
    vm::Engine engine = vm::default_engine();
    std::optional<std::string> trace;
    std::optional<std::string> can_log;
    std::optional<std::string> pcap;
    bool force = false; ///< replace existing output files of another kind
    /// The EPOS P's non-volatile memory: the downloaded program and the saved parameters are
    /// kept there across runs; without it they live in memory only.
    std::optional<std::string> state_dir;
    /// `eposp serve`: without --state-dir the EPOS P keeps its memory in its default state
    /// directory, as a device keeps its program over a power cycle; `eposp run` keeps none.
    bool state_by_default = false;
    ErrorFormat error_format = ErrorFormat::Human; ///< of the .st files' diagnostics
};

/// Adds FILES (required or not) and the options of SessionOptions to `command`.
void add_session_options(CLI::App& command, SessionOptions& options, bool program_required);

/// An EPOS P set up as the options say, for one run: the network added, the program loaded, the
/// traces open. Every mistake in the options is found by open(), before anything runs.
class DeviceSession {
public:
    static core::Result<std::unique_ptr<DeviceSession>> open(const SessionOptions& options,
                                                             core::Pace pace);
    ~DeviceSession();
    DeviceSession(const DeviceSession&) = delete;
    DeviceSession& operator=(const DeviceSession&) = delete;

    EposP& device() { return *device_; }
    /// Starts the program as --start says, which boots the networks; without a program on the
    /// command line, the stored program as its stored 0x5F51 says (10.37), and without one that
    /// starts, boots the networks alone.
    std::optional<core::Error> start();
    /// Stops the program (saving its RETAIN variables) and prints the boot report, each task's
    /// statistics, the errors raised and the watched variables; the exit code: kExitDeviceErrors
    /// when the program raised an error (a task fault, an overrun, a retain failure) or a trace
    /// could not be written.
    int finish(std::string_view command);

private:
    struct Traces;

    DeviceSession(const SessionOptions& options, std::optional<NetworkFile> network,
                  std::unique_ptr<EposP> device);
    /// The traces the options ask for: the axes of the simulated drives, both buses in the
    /// candump log, the CAN bus (port 2) in the pcap.
    static core::Result<std::unique_ptr<Traces>>
    open_traces(const SessionOptions& options, EposP& device,
                const std::optional<NetworkFile>& network);

    SessionOptions options_;
    std::optional<NetworkFile> network_;
    std::unique_ptr<EposP> device_;
    std::unique_ptr<Traces> traces_;
    bool has_program_ = false;
};

} // namespace eposp::device::cli
