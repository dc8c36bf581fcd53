// The ST unit-test library: TcUnit's functions as native functions over one suite's recorder.

#include "eposp/plctest/test_library.hpp"

#include "function_interface.hpp"
#include "native_value_text.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <functional>

namespace eposp::plctest {
namespace {

using vm::NativeType;
using vm::Scalar;

constexpr std::string_view kText = "STRING(255)"; // TcUnit's T_MaxString

struct ElementaryType {
    std::string_view name;
    NativeType type;
    Scalar scalar;
};

// The types of the typed assertions (AssertEquals_DINT …), TcUnit's set and the L-types.
constexpr ElementaryType kEqualsTypes[] = {
    {"BOOL", NativeType::Bool, Scalar::Bool},
    {"BYTE", NativeType::Byte, Scalar::U8},
    {"WORD", NativeType::Word, Scalar::U16},
    {"DWORD", NativeType::Dword, Scalar::U32},
    {"LWORD", NativeType::Lword, Scalar::U64},
    {"SINT", NativeType::Sint, Scalar::I8},
    {"INT", NativeType::Int, Scalar::I16},
    {"DINT", NativeType::Dint, Scalar::I32},
    {"LINT", NativeType::Lint, Scalar::I64},
    {"USINT", NativeType::Usint, Scalar::U8},
    {"UINT", NativeType::Uint, Scalar::U16},
    {"UDINT", NativeType::Udint, Scalar::U32},
    {"ULINT", NativeType::Ulint, Scalar::U64},
    {"TIME", NativeType::Time, Scalar::I64},
    {"LTIME", NativeType::Ltime, Scalar::I64},
    {"DATE", NativeType::Date, Scalar::I64},
    {"TIME_OF_DAY", NativeType::TimeOfDay, Scalar::I64},
    {"DATE_AND_TIME", NativeType::DateAndTime, Scalar::I64},
};
constexpr ElementaryType kReal{"REAL", NativeType::Real, Scalar::F32};
constexpr ElementaryType kLreal{"LREAL", NativeType::Lreal, Scalar::F64};

// TcUnit's AssertArrayEquals_* types (REAL and LREAL take a delta).
constexpr std::string_view kArrayTypes[] = {"BOOL", "BYTE",  "WORD", "DWORD", "LWORD",
                                            "SINT", "INT",   "DINT", "LINT",  "USINT",
                                            "UINT", "UDINT", "ULINT"};

FunctionParameter value(std::string name, const ElementaryType& type) {
    return {std::move(name), std::string(type.name), Passed::Value, type.scalar};
}
FunctionParameter text(std::string name) {
    return {std::move(name), std::string(kText), Passed::String};
}
FunctionParameter any(std::string name) {
    return {std::move(name), "ANY", Passed::Any};
}
FunctionParameter array(std::string name, std::string_view element) {
    return {std::move(name), fmt::format("ARRAY[*] OF {}", element), Passed::Array};
}
FunctionParameter flag(std::string name) {
    return value(std::move(name), {"BOOL", NativeType::Bool, Scalar::Bool});
}
FunctionParameter duration(std::string name) {
    return value(std::move(name), {"TIME", NativeType::Time, Scalar::I64});
}

/// One call of a library function: its arguments by parameter number.
class Call {
public:
    Call(vm::NativeArgs& args, const FunctionInterface& function)
        : args_(args), function_(function) {}

    /// A Value or Any parameter's value; a Value's bytes are copied into `storage`.
    vm::NativeValue value(std::size_t parameter, NativeType type,
                          std::array<std::uint8_t, 8>& storage) {
        const std::size_t at = function_.position(parameter);
        if (function_.parameters[parameter].passed == Passed::Any) {
            return args_.any(at);
        }
        const Scalar scalar = function_.parameters[parameter].scalar;
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
    bool flag(std::size_t parameter) {
        return args_.get<std::uint8_t>(function_.position(parameter)) != 0;
    }
    core::Duration duration(std::size_t parameter) {
        return core::Duration(args_.get<std::int64_t>(function_.position(parameter)));
    }
    double real(std::size_t parameter) {
        const std::size_t at = function_.position(parameter);
        return function_.parameters[parameter].scalar == Scalar::F32 ? args_.get<float>(at)
                                                                     : args_.get<double>(at);
    }
    std::string text(std::size_t parameter) { return args_.text(function_.position(parameter)); }
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

std::string with_message(std::string text, const std::string& message) {
    return message.empty() ? text : text + ": " + message;
}

std::string mismatch(const vm::NativeValue& expected, const vm::NativeValue& actual,
                     const Comparison& comparison) {
    if (comparison.types_differ) {
        return fmt::format("expected {} ({}), got {} ({})", literal(expected),
                           vm::native_type_name(expected.type), literal(actual),
                           vm::native_type_name(actual.type));
    }
    return fmt::format("expected {}, got {}", literal(expected), literal(actual));
}

using Body = std::function<bool(Call&, const Binding&, std::string_view name)>;

struct LibraryFunction {
    FunctionInterface interface;
    Body body;
};

Body equals_body(NativeType type) {
    return [type](Call& call, const Binding& binding, std::string_view name) {
        std::array<std::uint8_t, 8> expected_storage{};
        std::array<std::uint8_t, 8> actual_storage{};
        const vm::NativeValue expected = call.value(0, type, expected_storage);
        const vm::NativeValue actual = call.value(1, type, actual_storage);
        const Comparison comparison = compare(expected, actual);
        return binding.check(call.args(), name, comparison.equal, [&] {
            return with_message(mismatch(expected, actual, comparison), call.text(2));
        });
    };
}

Body string_equals_body() {
    return [](Call& call, const Binding& binding, std::string_view name) {
        const std::string expected = call.text(0);
        const std::string actual = call.text(1);
        return binding.check(call.args(), name, expected == actual, [&] {
            return with_message(fmt::format("expected '{}', got '{}'", expected, actual),
                                call.text(2));
        });
    };
}

Body real_equals_body(NativeType type) {
    return [type](Call& call, const Binding& binding, std::string_view name) {
        std::array<std::uint8_t, 8> expected_storage{};
        std::array<std::uint8_t, 8> actual_storage{};
        std::array<std::uint8_t, 8> delta_storage{};
        const vm::NativeValue expected = call.value(0, type, expected_storage);
        const vm::NativeValue actual = call.value(1, type, actual_storage);
        const vm::NativeValue delta = call.value(2, type, delta_storage);
        const bool passed = std::fabs(call.real(0) - call.real(1)) <= call.real(2);
        return binding.check(call.args(), name, passed, [&] {
            return with_message(fmt::format("expected {} within {}, got {}", literal(expected),
                                            literal(delta), literal(actual)),
                                call.text(3));
        });
    };
}

Body condition_body(bool wanted) {
    return [wanted](Call& call, const Binding& binding, std::string_view name) {
        const bool condition = call.flag(0);
        return binding.check(call.args(), name, condition == wanted, [&] {
            return with_message(fmt::format("expected {}, got {}", wanted ? "TRUE" : "FALSE",
                                            condition ? "TRUE" : "FALSE"),
                                call.text(1));
        });
    };
}

// AssertArrayEquals_*: the same number of elements, then element by element; the first
// difference is reported with its index in Expecteds. `delta` is the parameter of REAL's.
Body array_equals_body(std::optional<std::size_t> delta) {
    return [delta](Call& call, const Binding& binding, std::string_view name) {
        const vm::NativeArray expected = call.array(0);
        const vm::NativeArray actual = call.array(1);
        const std::size_t message = delta ? 3 : 2;
        if (expected.count != actual.count) {
            return binding.check(call.args(), name, false, [&] {
                return with_message(
                    fmt::format("expected {} elements, got {}", expected.count, actual.count),
                    call.text(message));
            });
        }
        const double tolerance = delta ? call.real(*delta) : 0.0;
        for (std::uint32_t i = 0; i < expected.count; ++i) {
            const vm::NativeValue e = expected.at(i);
            const vm::NativeValue a = actual.at(i);
            const bool equal =
                delta
                    ? std::fabs((e.bytes.size() == 4 ? e.as<float>() : e.as<double>()) -
                                (a.bytes.size() == 4 ? a.as<float>() : a.as<double>())) <= tolerance
                    : compare(e, a).equal;
            if (!equal) {
                return binding.check(call.args(), name, false, [&] {
                    return with_message(fmt::format("expected {} at index {}, got {}", literal(e),
                                                    std::int64_t{expected.lower} + i, literal(a)),
                                        call.text(message));
                });
            }
        }
        return true;
    };
}

std::vector<LibraryFunction> library_functions() {
    std::vector<LibraryFunction> functions;
    auto add = [&functions](std::string name, std::vector<FunctionParameter> parameters,
                            Body body) {
        functions.push_back({{std::move(name), std::move(parameters)}, std::move(body)});
    };
    add("TEST", {text("TestName")}, [](Call& call, const Binding& binding, std::string_view) {
        return binding.recorder.begin_test(call.text(0), binding.site(call.args(), "TEST"),
                                           binding.loop.now());
    });
    add("TEST_FINISHED", {}, [](Call&, const Binding& binding, std::string_view) {
        return binding.recorder.finish_test(binding.loop.now());
    });
    add(std::string(kCycleEndFunction), {}, [](Call&, const Binding& binding, std::string_view) {
        binding.recorder.end_cycle(binding.loop.now());
        return true;
    });
    add("WAIT_UNTIL", {flag("Condition"), duration("Timeout")},
        [](Call& call, const Binding& binding, std::string_view name) {
            return binding.recorder.wait_until(call.flag(0), call.duration(1),
                                               binding.site(call.args(), name), binding.loop.now());
        });
    add("ADVANCE_TIME", {duration("Duration")},
        [](Call& call, const Binding& binding, std::string_view name) {
            return binding.recorder.advance_time(call.duration(0), binding.site(call.args(), name),
                                                 binding.loop.now());
        });
    add("AssertEquals", {any("Expected"), any("Actual"), text("Message")},
        equals_body(NativeType::Bool)); // the types come with the values
    for (const ElementaryType& type : kEqualsTypes) {
        add(fmt::format("AssertEquals_{}", type.name),
            {value("Expected", type), value("Actual", type), text("Message")},
            equals_body(type.type));
    }
    for (const ElementaryType& type : {kReal, kLreal}) {
        add(fmt::format("AssertEquals_{}", type.name),
            {value("Expected", type), value("Actual", type), value("Delta", type), text("Message")},
            real_equals_body(type.type));
    }
    for (const std::string_view type : {"STRING", "WSTRING"}) {
        add(fmt::format("AssertEquals_{}", type),
            {{"Expected", std::string(type) + "(255)", Passed::String},
             {"Actual", std::string(type) + "(255)", Passed::String},
             text("Message")},
            string_equals_body());
    }
    add("AssertTrue", {flag("Condition"), text("Message")}, condition_body(true));
    add("AssertFalse", {flag("Condition"), text("Message")}, condition_body(false));
    for (const std::string_view type : kArrayTypes) {
        add(fmt::format("AssertArrayEquals_{}", type),
            {array("Expecteds", type), array("Actuals", type), text("Message")},
            array_equals_body(std::nullopt));
    }
    for (const ElementaryType& type : {kReal, kLreal}) {
        add(fmt::format("AssertArrayEquals_{}", type.name),
            {array("Expecteds", type.name), array("Actuals", type.name), value("Delta", type),
             text("Message")},
            array_equals_body(2));
    }
    return functions;
}

const std::vector<LibraryFunction>& functions() {
    static const std::vector<LibraryFunction> all = library_functions();
    return all;
}

} // namespace

std::string_view TestLibrary::source() {
    static const std::string text = [] {
        std::string declarations =
            "(* eposp's unit-test library (docs/testing-plc-code.md): native functions. *)\n";
        for (const LibraryFunction& function : functions()) {
            declarations += function.interface.declaration();
        }
        return declarations;
    }();
    return text;
}

void TestLibrary::register_natives(vm::NativeRegistry& natives, TestRecorder& recorder,
                                   const core::EventLoop& loop, PouFiles files) {
    auto binding = std::make_shared<const Binding>(Binding{recorder, loop, std::move(files)});
    for (const LibraryFunction& function : functions()) {
        natives.add(function.interface.name, function.interface.signature(),
                    [binding, &function](vm::NativeArgs& args) {
                        Call call(args, function.interface);
                        const bool result = function.body(call, *binding, function.interface.name);
                        args.set_result<std::uint8_t>(result ? 1 : 0);
                    });
    }
}

} // namespace eposp::plctest
