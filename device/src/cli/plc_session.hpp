#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/task_scheduler.hpp"

#include <memory>
#include <optional>
#include <string>

namespace eposp::device::cli {

/// A program image made ready to run the way `eposp run` and `eposp bench` run it: linked
/// against the natives a PLC offers (the standard library and the task clock), with its memory
/// cold-started and its tasks on a virtual-time event loop.
class PlcSession {
public:
    /// Verifies and links the image; the error says why it cannot run.
    static core::Result<std::unique_ptr<PlcSession>> open(vm::Image image);

    core::EventLoop& loop() { return loop_; }
    vm::Machine& machine() { return *machine_; }
    vm::TaskScheduler& scheduler() { return *scheduler_; }
    const vm::Image& image() const { return program_->image(); }

    /// The value of the variable at `path` (`Inst0.counter`) as an IEC literal.
    core::Result<std::string> value_of(const std::string& path) const;

private:
    PlcSession();

    core::EventLoop loop_{core::Pace::Virtual};
    vm::NativeRegistry natives_;
    std::optional<vm::Program> program_;
    std::optional<vm::Machine> machine_;
    std::optional<vm::TaskScheduler> scheduler_;
};

} // namespace eposp::device::cli
