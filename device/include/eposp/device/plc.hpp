#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/plc_runtime.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace eposp::device {

/// An error the PLC runtime raised, with the time it happened at.
struct RaisedError {
    core::TimePoint when;
    std::uint16_t code = 0;
    std::string text;
};

/// The programmable part of the EPOS P: a PLC runtime linked against the natives a PLC offers
/// (the standard library, and a clock that reads the loop's time for TON, TOF, TP and the RTC),
/// its tasks on the loop, its errors collected.
///
/// Neither copyable nor movable: the runtime refers to the natives and the error sink to this.
class Plc {
public:
    /// What the device adds to loading a program: a check that may refuse it (load() and
    /// verify() ask it), and what it sets up once the program is in.
    class LoadObserver {
    public:
        virtual ~LoadObserver() = default;
        virtual std::optional<core::Error> check(const vm::Image& image) const = 0;
        virtual void loaded(const vm::Image& image) = 0;
    };

    Plc(core::EventLoop& loop, vm::RuntimeConfig config);
    Plc(const Plc&) = delete;
    Plc& operator=(const Plc&) = delete;

    /// Verifies, links and loads a program image; the error says why it cannot run. The program
    /// does not start: runtime().start() starts it.
    std::optional<core::Error> load(vm::Image image);
    /// Whether load() would accept `image`, leaving the loaded program alone: verified and linked
    /// on a scratch runtime of the same natives and settings (a download is checked this way
    /// before it replaces anything).
    std::optional<core::Error> verify(vm::Image image) const;
    /// Lets `observer`, which outlives this, check and follow each load from now on.
    void observe_loads(LoadObserver& observer) { load_observer_ = &observer; }

    vm::PlcRuntime& runtime() { return runtime_; }
    /// The natives programs link against; more (the motion blocks) are added before a load.
    vm::NativeRegistry& natives() { return natives_; }
    const vm::PlcRuntime& runtime() const { return runtime_; }
    const vm::Image& image() const { return runtime_.image(); }
    const std::vector<RaisedError>& errors() const { return errors_; }
    /// Told of every error as it is raised (the device's error history).
    void on_error(std::function<void(const RaisedError& error)> handler) {
        error_handler_ = std::move(handler);
    }
    /// The value of the variable at `path` (`Inst0.counter`) as an IEC literal.
    core::Result<std::string> value_of(const std::string& path) const {
        return runtime_.read(path);
    }

private:
    core::EventLoop& loop_;
    vm::NativeRegistry natives_;
    std::vector<RaisedError> errors_;
    std::function<void(const RaisedError&)> error_handler_;
    vm::RuntimeConfig scratch_config_; ///< verify()'s runtime: the limits without a RETAIN store
    LoadObserver* load_observer_ = nullptr;
    vm::PlcRuntime runtime_;
};

} // namespace eposp::device
