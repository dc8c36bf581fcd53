// The ST unit-test library: TcUnit's functions as native functions over one suite's recorder.

#include "eposp/plctest/test_library.hpp"

#include "library_call.hpp"
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
FunctionParameter duration(std::string name) {
    return value(std::move(name), {"TIME", NativeType::Time, Scalar::I64});
}

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

// A WSTRING's characters are compared and shown as UTF-8, between its literal's double quotes.
Body string_equals_body(bool wide) {
    return [wide](Call& call, const Binding& binding, std::string_view name) {
        const std::string expected = wide ? call.wide_text(0) : call.text(0);
        const std::string actual = wide ? call.wide_text(1) : call.text(1);
        const char quote = wide ? '"' : '\'';
        return binding.check(call.args(), name, expected == actual, [&] {
            return with_message(
                fmt::format("expected {1}{0}{1}, got {1}{2}{1}", expected, quote, actual),
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
    add("WAIT_UNTIL", {bool_parameter("Condition"), duration("Timeout")},
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
            string_equals_body(type == "WSTRING"));
    }
    add("AssertTrue", {bool_parameter("Condition"), text("Message")}, condition_body(true));
    add("AssertFalse", {bool_parameter("Condition"), text("Message")}, condition_body(false));
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
    std::ranges::move(fault_functions(), std::back_inserter(functions));
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
                                   const core::EventLoop& loop, PouFiles files,
                                   device::FaultInjector& faults) {
    register_functions(
        natives, functions(),
        std::make_shared<const Binding>(Binding{recorder, loop, std::move(files), faults}));
}

} // namespace eposp::plctest
