#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/plc_runtime.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eposp::device::cli {

/// An error the runtime raised during a run, with the virtual time it happened at.
struct RaisedError {
    core::TimePoint when;
    std::uint16_t code = 0;
    std::string text;
};

/// A program loaded into a PLC runtime the way `eposp run` and `eposp bench` run it: linked
/// against the natives a PLC offers (the standard library and the task clock), its tasks on a
/// virtual-time event loop, the runtime's errors collected.
class PlcSession {
public:
    /// Verifies, links and loads the image; the error says why it cannot run.
    static core::Result<std::unique_ptr<PlcSession>> open(vm::Image image,
                                                          vm::RuntimeConfig config = {});

    core::EventLoop& loop() { return loop_; }
    vm::PlcRuntime& runtime() { return *runtime_; }
    const vm::Image& image() const { return runtime_->image(); }
    const std::vector<RaisedError>& errors() const { return errors_; }

    /// The value of the variable at `path` (`Inst0.counter`) as an IEC literal.
    core::Result<std::string> value_of(const std::string& path) const {
        return runtime_->read(path);
    }

private:
    PlcSession() = default;

    core::EventLoop loop_{core::Pace::Virtual};
    vm::NativeRegistry natives_;
    std::vector<RaisedError> errors_;
    std::unique_ptr<vm::PlcRuntime> runtime_;
};

} // namespace eposp::device::cli
