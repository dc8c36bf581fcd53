#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/device/fault_injector.hpp"
#include "eposp/plctest/test_recorder.hpp"
#include "eposp/vm/native.hpp"

#include <functional>
#include <string>
#include <string_view>

namespace eposp::plctest {

/// Where a POU's source is: its file as the report names it (empty when unknown).
using PouFiles = std::function<std::string(std::string_view pou)>;

/// The name of the function the harness calls at the end of every cycle of a suite.
inline constexpr std::string_view kCycleEndFunction = "EPOSP_TEST_CYCLE_END";

/// The ST unit-test library (docs/testing-plc-code.md), TcUnit's functions by TcUnit's names:
/// TEST / TEST_FINISHED, AssertEquals (ANY) and its typed forms, AssertEquals_REAL / LREAL with
/// a delta, AssertTrue / AssertFalse, AssertArrayEquals_*, and, because time is virtual,
/// WAIT_UNTIL and ADVANCE_TIME, and the Inject* functions that inject faults into the machine.
/// Each is a native function: declared in ST (source(), linked with every suite) and run in C++
/// against one suite's recorder and device.
class TestLibrary {
public:
    /// The declarations, for compiler::compile's linked libraries.
    static std::string_view source();

    /// Registers the bodies, bound to `recorder`, reading the machine time from `loop`,
    /// naming the file of a failure through `files` and injecting faults through `faults`.
    static void register_natives(vm::NativeRegistry& natives, TestRecorder& recorder,
                                 const core::EventLoop& loop, PouFiles files,
                                 device::FaultInjector& faults);
};

} // namespace eposp::plctest
