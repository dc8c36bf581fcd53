#pragma once

// What the native functions of the test library and the fault library share: a call's
// arguments by parameter number, the suite they report to, and their registration.

#include "eposp/core/event_loop.hpp"
#include "eposp/device/fault_injector.hpp"
#include "eposp/plctest/test_library.hpp"
#include "eposp/plctest/test_recorder.hpp"
#include "function_interface.hpp"

#include <array>
#include <cstring>
#include <fmt/format.h>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::plctest {

/// One call of a library function: its arguments by parameter number.
class Call {
public:
    Call(vm::NativeArgs& args, const FunctionInterface& function)
        : args_(args), function_(function) {}

    /// A Value or Any parameter's value; a Value's bytes are copied into `storage`.
    vm::NativeValue value(std::size_t parameter, vm::NativeType type,
                          std::array<std::uint8_t, 8>& storage) {
        const std::size_t at = function_.position(parameter);
        if (function_.parameters[parameter].passed == Passed::Any) {
            return args_.any(at);
        }
        const vm::Scalar scalar = function_.parameters[parameter].scalar;
        const std::uint32_t size = vm::scalar_size(scalar);
        switch (size) {
        case 1:
            copy(storage, args_.get<std::uint8_t>(at));
            break;
        case 2:
            copy(storage, args_.get<std::uint16_t>(at));
            break;
        case 4:
            copy(storage, args_.get<std::uint32_t>(at));
            break;
        default:
            copy(storage, args_.get<std::uint64_t>(at));
            break;
        }
        return {type, std::span<const std::uint8_t>(storage.data(), size)};
    }
    /// An elementary Value parameter as T (its scalar's C++ type).
    template <typename T>
    T scalar(std::size_t parameter) {
        return args_.get<T>(function_.position(parameter));
    }
    bool flag(std::size_t parameter) {
        return args_.get<std::uint8_t>(function_.position(parameter)) != 0;
    }
    core::Duration duration(std::size_t parameter) {
        return core::Duration(args_.get<std::int64_t>(function_.position(parameter)));
    }
    double real(std::size_t parameter) {
        const std::size_t at = function_.position(parameter);
        return function_.parameters[parameter].scalar == vm::Scalar::F32 ? args_.get<float>(at)
                                                                         : args_.get<double>(at);
    }
    std::string text(std::size_t parameter) { return args_.text(function_.position(parameter)); }
    std::string wide_text(std::size_t parameter) {
        return args_.wide_text(function_.position(parameter));
    }
    vm::NativeArray array(std::size_t parameter) {
        return args_.array(function_.position(parameter));
    }
    vm::NativeArgs& args() { return args_; }

private:
    template <typename T>
    static void copy(std::array<std::uint8_t, 8>& storage, T value) {
        std::memcpy(storage.data(), &value, sizeof(T));
    }

    vm::NativeArgs& args_;
    const FunctionInterface& function_;
};

/// What the bodies share: the suite's recorder, the clock, the files of the POUs.
struct Binding {
    TestRecorder& recorder;
    const core::EventLoop& loop;
    PouFiles files;
    device::FaultInjector& faults;

    CallSite site(const vm::NativeArgs& args, std::string_view function) const {
        const vm::NativeCallSite at = args.call_site();
        const std::size_t key =
            std::hash<std::string>{}(fmt::format("{}:{}:{}", function, at.pou, at.line));
        return {key, {files ? files(at.pou) : std::string(), at.line}};
    }
    /// An assertion's outcome; the call site is looked up only when it failed.
    bool check(vm::NativeArgs& args, std::string_view function, bool passed,
               const std::function<std::string()>& describe) const {
        return passed || recorder.check(false, site(args, function), describe);
    }
};

using Body = std::function<bool(Call&, const Binding&, std::string_view name)>;

struct LibraryFunction {
    FunctionInterface interface;
    Body body;
};

/// The functions that inject faults into the suite's machine (fault_functions.cpp).
std::vector<LibraryFunction> fault_functions();

/// Registers `functions` (which must outlive the registry's use) with their bodies bound to
/// `binding`; each returns its body's BOOL.
inline void register_functions(vm::NativeRegistry& natives,
                               const std::vector<LibraryFunction>& functions,
                               std::shared_ptr<const Binding> binding) {
    for (const LibraryFunction& function : functions) {
        natives.add(function.interface.name, function.interface.signature(),
                    [binding, &function](vm::NativeArgs& args) {
                        Call call(args, function.interface);
                        const bool result = function.body(call, *binding, function.interface.name);
                        args.set_result<std::uint8_t>(result ? 1 : 0);
                    });
    }
}

} // namespace eposp::plctest
