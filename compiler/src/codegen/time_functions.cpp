// The named time and date functions of IEC 61131-3 ed. 3, table 30 (ADD_TIME, SUB_DT_DT,
// CONCAT_DATE_TOD, ...): the same operations as `+` and `-` on these types (and `*`, `/` of a
// TIME by a number), with their parameter types checked as the table gives them.

#include "pou_generator.hpp"

#include <array>
#include <fmt/format.h>

namespace eposp::compiler::codegen {

using E = ast::ElementaryType;

namespace {

struct TimeFunction {
    std::string_view name;
    ast::BinaryOperator op;
    E first;
    E second; // Lint: any number (MUL_TIME, DIV_TIME)
};

constexpr std::array kTimeFunctions{
    TimeFunction{"ADD_TIME", ast::BinaryOperator::Add, E::Time, E::Time},
    TimeFunction{"ADD_TOD_TIME", ast::BinaryOperator::Add, E::TimeOfDay, E::Time},
    TimeFunction{"ADD_DT_TIME", ast::BinaryOperator::Add, E::DateAndTime, E::Time},
    TimeFunction{"SUB_TIME", ast::BinaryOperator::Subtract, E::Time, E::Time},
    TimeFunction{"SUB_DATE_DATE", ast::BinaryOperator::Subtract, E::Date, E::Date},
    TimeFunction{"SUB_TOD_TIME", ast::BinaryOperator::Subtract, E::TimeOfDay, E::Time},
    TimeFunction{"SUB_TOD_TOD", ast::BinaryOperator::Subtract, E::TimeOfDay, E::TimeOfDay},
    TimeFunction{"SUB_DT_TIME", ast::BinaryOperator::Subtract, E::DateAndTime, E::Time},
    TimeFunction{"SUB_DT_DT", ast::BinaryOperator::Subtract, E::DateAndTime, E::DateAndTime},
    TimeFunction{"MUL_TIME", ast::BinaryOperator::Multiply, E::Time, E::Lint},
    TimeFunction{"DIV_TIME", ast::BinaryOperator::Divide, E::Time, E::Lint},
    // DATE and TOD are nanoseconds since 1970 and since midnight: their sum is the DT.
    TimeFunction{"CONCAT_DATE_TOD", ast::BinaryOperator::Add, E::Date, E::TimeOfDay},
};

const TimeFunction* find_time_function(std::string_view name) {
    for (const TimeFunction& function : kTimeFunctions) {
        if (function.name == name) {
            return &function;
        }
    }
    return nullptr;
}

} // namespace

bool is_time_function(std::string_view name) {
    return find_time_function(name) != nullptr;
}

std::optional<Value> PouGenerator::time_function(const std::string& name,
                                                 const Arguments& arguments,
                                                 const Destination* dest,
                                                 const SourceRange& range) {
    const TimeFunction& function = *find_time_function(name);
    if (arguments.size() != 2) {
        error(DiagnosticCode::E0306, range, fmt::format("{} takes two arguments", name));
        return std::nullopt;
    }
    const ast::Expression& first = *arguments[0]->value;
    const ast::Expression& second = *arguments[1]->value;
    const auto left = value_as(first, types_.elementary(function.first));
    if (!left) {
        return std::nullopt;
    }
    if (function.second == E::Lint) {
        return scale_time(function.op == ast::BinaryOperator::Multiply, *left, second, dest);
    }
    const auto right = value_as(second, types_.elementary(function.second));
    if (!right) {
        return std::nullopt;
    }
    if (name == "CONCAT_DATE_TOD") {
        const sema::Type& dt = types_.elementary(E::DateAndTime);
        const vm::Operand result = result_operand(dt, dest);
        emit(op_width("Add", dt), result, left->operand, right->operand);
        return Value{result, &dt};
    }
    return apply(function.op, *left, *right, dest, range);
}

} // namespace eposp::compiler::codegen
