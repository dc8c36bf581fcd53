#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/vm/forced_values.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/marker_area.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/process_image.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/retain_store.hpp"
#include "eposp/vm/runtime_error.hpp"
#include "eposp/vm/symbol_lookup.hpp"
#include "eposp/vm/task_dispatcher.hpp"

#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

namespace eposp::vm {

/// How a program starts (Program Control 0x5F51, EPOS P firmware specification 10.37, table 31).
enum class StartMode : std::uint16_t {
    Cold = 1, ///< every variable, RETAIN ones included, to its initial value
    Warm = 2, ///< RETAIN variables keep their values from before the stop or power loss
    Hot = 3,  ///< as Warmstart (table 31: "same as Warmstart")
};

enum class ProgramState : std::uint8_t { NotLoaded, Stopped, Running };

/// What the outputs of a faulted task, or of a stopped program, become.
enum class SafeState : std::uint8_t { Hold, Zero };

struct RuntimeConfig {
    CostModel cost;
    /// The watchdog: instructions one cycle of a task may execute. Finite by default, so that
    /// an endless loop stops its task (Interpreter Error 0x6181) instead of the process.
    std::uint64_t watchdog_instructions = 100'000'000;
    SafeState safe_state = SafeState::Zero;
    /// Where RETAIN variables persist; without it a warm start finds no stored values.
    std::optional<std::filesystem::path> retain_file;
    /// Bytes of RETAIN data the controller holds (MCD EPOS P 60 W: 512, 0102h notes).
    std::uint32_t retain_capacity = 512;
    /// While running, retain data is saved this often when it changed; zero: only at stop.
    core::Duration retain_save_interval{};
    /// What runs the loaded programs (the results are the same; the speed is not).
    Engine engine = default_engine();
    /// Record which lines and branches run (PlcRuntime::coverage). Forces the interpreter,
    /// whatever `engine` says: compiled code counts nothing.
    Coverage coverage = Coverage::Off;
};

/// The PLC: a loaded program, its tasks on the event loop, RETAIN variables, the DS-405 process
/// image and the marker area, its errors to an error sink, and online access to its variables
/// by name. The device drives it through Program Control 0x5F51 (load, start, stop) and feeds
/// its process image; docs/runtime.md explains it with examples.
class PlcRuntime : private TaskHooks {
public:
    /// `natives` must outlive the runtime; `errors` receives every error it raises.
    PlcRuntime(core::EventLoop& loop, const NativeRegistry& natives, RuntimeConfig config,
               ErrorSink errors);
    ~PlcRuntime() override;
    PlcRuntime(const PlcRuntime&) = delete;
    PlcRuntime& operator=(const PlcRuntime&) = delete;

    // Program control.
    /// Verifies and links the image and checks that its RETAIN data, process-image and marker
    /// bindings fit this controller; refused with the reason, and while a program runs.
    std::optional<core::Error> load(Image image);
    /// Refused when no program is loaded or one is running. Statistics start afresh.
    std::optional<core::Error> start(StartMode mode);
    /// Stops the tasks, saves the RETAIN variables and puts the outputs in the safe state.
    void stop();
    /// Stops the program and forgets it (CiA 302-3 "clear program", EPOS P 0x1011 "eras"): the
    /// state is NotLoaded until the next load.
    void unload();
    ProgramState state() const;
    /// The value of 0x5F51: 0 when stopped, else the mode the program was started in.
    std::uint16_t program_control() const;

    // Tasks (table indices of the image's tasks).
    const Image& image() const { return program_->image(); }
    std::optional<std::size_t> task_index(std::string_view name) const;
    /// The device's event for an event task (see TaskDispatcher::raise_event); ignored while
    /// the program is not running.
    void raise_event(std::size_t task);
    /// Runs the cyclic tasks whose interval is a multiple of `period` in step with a clock of
    /// that period (TaskDispatcher::align); ignored while the program is not running.
    void align_cycles(core::TimePoint anchor, core::Duration period);
    /// The watchdog of one task, instead of RuntimeConfig::watchdog_instructions (kept until
    /// the next load).
    void set_watchdog(std::size_t task, std::uint64_t instructions);
    const TaskStatistics& statistics(std::size_t task) const;
    bool task_faulted(std::size_t task) const;
    /// "division by zero in Main at line 3" for a faulted task.
    std::string fault_text(std::size_t task) const { return machine_->describe_fault(task); }
    /// Where a faulted task stopped (its POU and line), for reports that name the file.
    const Fault& fault(std::size_t task) const { return machine_->task(task).fault; }

    // The device's side of the I/O.
    ProcessImage& process_image() { return process_image_; }
    const MarkerArea& markers() const { return markers_; }
    std::span<const std::uint8_t> memory() const { return machine_->memory(); }

    /// The lines and branches of the loaded program run since its load, by POU name (starts
    /// and stops do not reset them; the next load does). Empty unless RuntimeConfig::coverage
    /// is Coverage::Record or when no program is loaded.
    CoverageReport coverage() const;

    // Online access by variable path (`Inst0.counter`, `Inst0.axis[2].pos`), also while running.
    /// The value as an IEC literal.
    core::Result<std::string> read(std::string_view path) const;
    /// Writes the variable's bytes (little-endian, its size exactly) once.
    std::optional<core::Error> write(std::string_view path, std::span<const std::uint8_t> bytes);
    /// Holds the variable at these bytes before and after every task cycle until unforced.
    std::optional<core::Error> force(std::string_view path, std::span<const std::uint8_t> bytes);
    std::optional<core::Error> unforce(std::string_view path);
    const ForcedValues& forced() const { return forced_; }

    template <typename T>
    requires std::is_trivially_copyable_v<T> std::optional<core::Error>
    write_value(std::string_view path, T value) {
        return write(path, as_bytes(value));
    }
    template <typename T>
    requires std::is_trivially_copyable_v<T> std::optional<core::Error>
    force_value(std::string_view path, T value) {
        return force(path, as_bytes(value));
    }

private:
    template <typename T>
    static std::vector<std::uint8_t> as_bytes(T value) {
        std::vector<std::uint8_t> bytes(sizeof(T));
        std::memcpy(bytes.data(), &value, sizeof(T));
        return bytes;
    }

    TaskHooks& hooks() { return *this; }
    void before_cycle(std::size_t task) override;
    void after_cycle(std::size_t task) override;
    void on_fault(std::size_t task) override;
    void on_overrun(std::size_t task, std::uint16_t code) override;

    void report(std::uint16_t code, std::string text, std::optional<std::size_t> task);
    core::Result<VariableLocation> writable(std::string_view path,
                                            std::span<const std::uint8_t> bytes) const;
    void restore_retain();
    void save_retain_if_changed();
    std::vector<std::uint8_t> retained_bytes() const;

    core::EventLoop& loop_;
    const NativeRegistry& natives_;
    RuntimeConfig config_;
    ErrorSink errors_;
    std::unique_ptr<Program> program_;
    std::unique_ptr<Machine> machine_;
    std::unique_ptr<TaskDispatcher> dispatcher_;
    std::vector<std::vector<IoBinding>> task_bindings_; ///< per task: its located variables
    std::optional<RetainStore> retain_store_;
    std::optional<std::vector<std::uint8_t>> retain_saved_; ///< what the store holds, if known
    core::ScopedTimer retain_timer_;
    ProcessImage process_image_;
    MarkerArea markers_;
    ForcedValues forced_;
    std::optional<StartMode> running_mode_;
};

} // namespace eposp::vm
