// Time and date arithmetic of IEC 61131-3 ed. 3, table 30: `+` and `-` on durations and points
// in time, `*` and `/` of a TIME by a number, and the named functions (ADD_TIME, SUB_DT_DT,
// CONCAT_DATE_TOD, ...) with the operand types of their manifest row (vm/stdlib/manifest.hpp).
// The typing stage decides every result type (types/operator_typing.cpp, time_arithmetic, and
// standard_function_typing.cpp); code generation only lays the operation out for it.

#include "eposp/vm/stdlib/manifest.hpp"
#include "pou_generator.hpp"

namespace eposp::compiler::codegen {

using E = ast::ElementaryType;

std::optional<Value> PouGenerator::time_function(const types::CallTarget& target,
                                                 const Arguments& arguments,
                                                 const Destination* dest) {
    using vm::stdlib::Operation;
    const vm::stdlib::StandardFunction& function = *vm::stdlib::find_standard_function(target.name);
    const vm::stdlib::TimeRule& rule = function.time;
    if (target.result == nullptr) {
        program_.refused_by_checks(DiagnosticCode::E0305); // types/standard_function_typing.cpp
        return std::nullopt;
    }
    // vm::NativeType lists the elementary types in ast::ElementaryType's order.
    const auto type = [&](vm::NativeType t) -> const sema::Type& {
        return types_.elementary(static_cast<E>(t));
    };
    // An extensible ADD or MUL (table 24) steps from left to right, each step with the row the
    // typing stage recorded for the last: ADD(tod, t1, t2) is (tod + t1) + t2.
    auto result = value_as(*arguments[0]->value, type(rule.first));
    const auto op = function.operation == Operation::Add ? ast::BinaryOperator::Add
                                                         : ast::BinaryOperator::Subtract;
    for (std::size_t i = 1; result && i < arguments.size(); ++i) {
        const Destination* into = i + 1 == arguments.size() ? dest : nullptr;
        const ast::Expression& next = *arguments[i]->value;
        if (rule.scaled) {
            result = scale_time(function.operation == Operation::Multiply, *result, next,
                                *target.result, into);
            continue;
        }
        const auto right = value_as(next, type(rule.second));
        // CONCAT_DATE_TOD adds too: DATE and TOD are nanoseconds since 1970 and since midnight.
        result = right ? time_arithmetic(op, *result, *right, *target.result, into) : std::nullopt;
    }
    return result;
}

std::optional<Value> PouGenerator::time_arithmetic(ast::BinaryOperator op, const Value& left,
                                                   const Value& right, const sema::Type& result,
                                                   const Destination* dest) {
    using Op = ast::BinaryOperator;
    if ((op != Op::Add && op != Op::Subtract) || !sema::is_time_like(result)) {
        program_.refused_by_checks(DiagnosticCode::E0303); // types/operator_typing.cpp
        return std::nullopt;
    }
    if (result.elementary == E::TimeOfDay || result.elementary == E::Ltod) {
        // A time of day moved by a duration wraps around midnight: a native (vm/README).
        const auto native = op == Op::Add ? vm::stdlib::native_binding("ADD_TOD_TIME")
                                          : vm::stdlib::native_binding("SUB_TOD_TIME");
        call_native(native.name, native.signature, {left, right});
        return native_result(native.signature, result, dest);
    }
    // Durations and points in time are all nanoseconds.
    const vm::Operand result_at = result_operand(result, dest);
    emit(op_width(op == Op::Add ? "Add" : "Sub", result), result_at, left.operand, right.operand);
    return Value{result_at, &result};
}

std::optional<Value> PouGenerator::scale_time(bool multiply, const Value& time,
                                              const ast::Expression& factor,
                                              const sema::Type& result, const Destination* dest) {
    const sema::Type& lint = types_.elementary(E::Lint);
    const auto value = eval(factor, &lint);
    if (!value) {
        return std::nullopt;
    }
    const bool real = sema::is_real(*value->type);
    if (!real && !sema::is_integer(*value->type)) {
        program_.refused_by_checks(DiagnosticCode::E0304); // types/operator_typing.cpp
        return std::nullopt;
    }
    const sema::Type& wide = real ? types_.elementary(E::Lreal) : lint;
    const auto converted = explicit_convert(*value, wide, nullptr);
    const auto variant = real ? vm::stdlib::Variant::Wide : vm::stdlib::Variant::Base;
    const auto native = multiply ? vm::stdlib::native_binding("MUL_TIME", variant)
                                 : vm::stdlib::native_binding("DIV_TIME", variant);
    call_native(native.name, native.signature, {time, *converted});
    return native_result(native.signature, result, dest);
}

} // namespace eposp::compiler::codegen
