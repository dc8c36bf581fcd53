// The named time and date functions of IEC 61131-3 ed. 3, table 30 (ADD_TIME, SUB_DT_DT,
// CONCAT_DATE_TOD, ...): the same operations as `+` and `-` on these types (and `*`, `/` of a
// TIME by a number), with the operand types of their manifest row (vm/stdlib/manifest.hpp).

#include "eposp/vm/stdlib/manifest.hpp"
#include "pou_generator.hpp"

namespace eposp::compiler::codegen {

using E = ast::ElementaryType;

std::optional<Value> PouGenerator::time_function(const std::string& name,
                                                 const Arguments& arguments,
                                                 const Destination* dest) {
    using vm::stdlib::Operation;
    const vm::stdlib::StandardFunction& function = *vm::stdlib::find_standard_function(name);
    const vm::stdlib::TimeRule& rule = function.time;
    // vm::NativeType lists the elementary types in ast::ElementaryType's order.
    const auto type = [&](vm::NativeType t) -> const sema::Type& {
        return types_.elementary(static_cast<E>(t));
    };
    const ast::Expression& first = *arguments[0]->value;
    const ast::Expression& second = *arguments[1]->value;
    const auto left = value_as(first, type(rule.first));
    if (!left) {
        return std::nullopt;
    }
    if (rule.scaled) {
        return scale_time(function.operation == Operation::Multiply, *left, second, dest);
    }
    const auto right = value_as(second, type(rule.second));
    if (!right) {
        return std::nullopt;
    }
    if (rule.result == vm::NativeType::DateAndTime && rule.first == vm::NativeType::Date) {
        // CONCAT_DATE_TOD: DATE and TOD are nanoseconds since 1970 and since midnight.
        const sema::Type& dt = type(rule.result);
        const vm::Operand result = result_operand(dt, dest);
        emit(op_width("Add", dt), result, left->operand, right->operand);
        return Value{result, &dt};
    }
    return apply(function.operation == Operation::Add ? ast::BinaryOperator::Add
                                                      : ast::BinaryOperator::Subtract,
                 *left, *right, dest);
}

} // namespace eposp::compiler::codegen
