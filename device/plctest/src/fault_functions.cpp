// The test library's fault injection (docs/testing-plc-code.md, "Injecting faults"): thin
// functions over device::FaultInjector. A test's body runs every cycle, so each call site
// injects once per test; a fault the device refuses (no such axis) fails the test.

#include "library_call.hpp"

namespace eposp::plctest {
namespace {

using vm::Scalar;

FunctionParameter axis() {
    return {"Axis", "USINT", Passed::Value, Scalar::U8};
}
/// Runs `inject` at the first call from this site in the running test; TRUE once injected.
Body once(std::function<std::optional<core::Error>(Call&, device::FaultInjector&)> inject) {
    return [inject](Call& call, const Binding& binding, std::string_view name) {
        const CallSite site = binding.site(call.args(), name);
        if (!binding.recorder.first_call(site)) {
            return true;
        }
        if (auto error = inject(call, binding.faults)) {
            binding.recorder.fail_running(site, fmt::format("{}: {}", name, error->message));
            return false;
        }
        return true;
    };
}

device::AxisTarget axis_of(Call& call) {
    return {call.scalar<std::uint8_t>(0)};
}

} // namespace

std::vector<LibraryFunction> fault_functions() {
    std::vector<LibraryFunction> functions;
    auto add = [&functions](std::string name, std::vector<FunctionParameter> parameters,
                            Body body) {
        functions.push_back({{std::move(name), std::move(parameters)}, std::move(body)});
    };
    add("InjectHeartbeatLoss", {axis()}, once([](Call& call, device::FaultInjector& faults) {
            return faults.drop_heartbeat(axis_of(call));
        }));
    add("RestoreHeartbeat", {axis()}, once([](Call& call, device::FaultInjector& faults) {
            return faults.restore_heartbeat(axis_of(call));
        }));
    add("InjectLimitSwitch", {axis(), bool_parameter("Positive"), bool_parameter("Pressed")},
        once([](Call& call, device::FaultInjector& faults) {
            const auto which = call.flag(1) ? drives::epos2::LimitSwitch::Positive
                                            : drives::epos2::LimitSwitch::Negative;
            return faults.set_limit_switch(axis_of(call), which, call.flag(2));
        }));
    add("InjectDriveError", {axis(), {"ErrorCode", "WORD", Passed::Value, Scalar::U16}},
        once([](Call& call, device::FaultInjector& faults) {
            return faults.raise_drive_error(axis_of(call), call.scalar<std::uint16_t>(1));
        }));
    add("InjectPdoFault",
        {axis(),
         {"Pdo", "USINT", Passed::Value, Scalar::U8},
         bool_parameter("FromDrive"),
         {"Frames", "UDINT", Passed::Value, Scalar::U32},
         bool_parameter("Drop")},
        once([](Call& call, device::FaultInjector& faults) {
            return faults.corrupt_pdo(
                axis_of(call),
                call.flag(2) ? device::PdoDirection::Tpdo : device::PdoDirection::Rpdo,
                call.scalar<std::uint8_t>(1),
                call.flag(4) ? device::PdoFault::Drop : device::PdoFault::Shorten,
                call.scalar<std::uint32_t>(3));
        }));
    return functions;
}

} // namespace eposp::plctest
