// The constants of time and date values (table 30 and the conversions of table 22), computed by
// the VM's own functions (vm/stdlib/time_arithmetic.hpp) on nanosecond counts, as code
// generation lays each out (codegen/time_functions.cpp, standard_functions.cpp's
// explicit_convert): sums and differences modulo 2^64, a TIME_OF_DAY wrapping at midnight, a
// TIME scaled by an integer (as LINT, wrapping) or by a real (as LREAL, rounded to the
// nanosecond), a time counted as a number in its unit (sema::number_unit). A division by zero
// is no constant: it stops the task at run time.

#include "constant_folder.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "eposp/vm/stdlib/time_arithmetic.hpp"

namespace eposp::compiler::types {

namespace {

namespace vs = vm::detail;
using E = ast::ElementaryType;

bool time_of_day(const sema::Type& type) {
    return type.elementary == E::TimeOfDay || type.elementary == E::Ltod;
}

std::optional<std::int64_t> nanoseconds(const Constant& constant) {
    const auto* ns = std::get_if<std::int64_t>(&constant);
    return ns != nullptr ? std::optional(*ns) : std::nullopt;
}

} // namespace

std::optional<Constant> ConstantFolder::time_value(const ast::BinaryExpression& node,
                                                   const sema::Type& type) const {
    using Op = ast::BinaryOperator;
    const Constant* left = program_.constant_of(*node.left);
    const Constant* right = program_.constant_of(*node.right);
    const sema::Type* right_type = program_.type_of(*node.right);
    const auto l = left != nullptr ? nanoseconds(*left) : std::nullopt;
    if (!l || right == nullptr || right_type == nullptr || !sema::is_time_like(type)) {
        return std::nullopt; // a pointer moved is no constant
    }
    if (node.op == Op::Multiply || node.op == Op::Divide) {
        return scaled_time(node.op == Op::Multiply, *l, *right, types_.unranged(*right_type));
    }
    const auto r = sema::is_time_like(*right_type) ? nanoseconds(*right) : std::nullopt;
    if (!r || (node.op != Op::Add && node.op != Op::Subtract)) {
        return std::nullopt;
    }
    return moved_time(node.op == Op::Add, *l, *r, type);
}

std::optional<Constant> ConstantFolder::moved_time(bool add, std::int64_t left, std::int64_t right,
                                                   const sema::Type& result) const {
    if (time_of_day(result)) {
        return add ? vm::stdlib::add_tod_time(left, right) : vm::stdlib::sub_tod_time(left, right);
    }
    return add ? vs::add(left, right) : vs::sub(left, right); // Add64, Sub64
}

std::optional<Constant> ConstantFolder::scaled_time(bool multiply, std::int64_t time,
                                                    const Constant& factor,
                                                    const sema::Type& factor_type) const {
    const bool real = sema::is_real(factor_type);
    if (!real && !sema::is_integer(factor_type)) {
        return std::nullopt;
    }
    const auto wide = convert(factor, factor_type, types_.elementary(real ? E::Lreal : E::Lint));
    if (!wide) {
        return std::nullopt;
    }
    if (real) {
        const double f = std::get<double>(*wide);
        return multiply ? std::optional(vm::stdlib::mul_time(time, f))
                        : vm::stdlib::div_time(time, f);
    }
    const std::int64_t n = std::get<std::int64_t>(*wide);
    return multiply ? std::optional(vm::stdlib::mul_time(time, n)) : vm::stdlib::div_time(time, n);
}

std::optional<Constant> ConstantFolder::time_function(std::string_view name,
                                                      const std::vector<Constant>& values,
                                                      const std::vector<const sema::Type*>& types,
                                                      const sema::Type& result) const {
    // Table 30's functions: the first input as its row's type (the same nanoseconds, TIME or
    // LTIME), then the operation the operator of that name computes; an extensible ADD or MUL
    // (table 24) from left to right, each step as its last row.
    const vm::stdlib::StandardFunction* function = vm::stdlib::find_standard_function(name);
    if (function == nullptr) {
        return std::nullopt;
    }
    using vm::stdlib::Operation;
    const bool add = function->operation == Operation::Add;
    const bool multiply = function->operation == Operation::Multiply;
    std::optional<Constant> time = nanoseconds(values.front());
    for (std::size_t i = 1; time && i < values.size(); ++i) {
        const std::int64_t ns = std::get<std::int64_t>(*time);
        if (function->time.scaled) {
            time = scaled_time(multiply, ns, values[i], *types[i]);
            continue;
        }
        const auto other = nanoseconds(values[i]);
        time = other ? moved_time(add, ns, *other, result) : std::nullopt;
    }
    return time;
}

std::optional<Constant> ConstantFolder::explicit_conversion(const Constant& constant,
                                                            const sema::Type& from,
                                                            const sema::Type& to) const {
    const sema::Type& target = types_.unranged(to);
    if (from.kind == sema::TypeKind::String || target.kind == sema::TypeKind::String) {
        return text_conversion(constant, from, target); // constant_text_conversions.cpp
    }
    const bool from_time = sema::is_time_like(from);
    const bool to_time = sema::is_time_like(target);
    if (!from_time && !to_time) {
        return convert(constant, from, target);
    }
    if (from_time && to_time) {
        // DT_TO_DATE and DT_TO_TOD's natives take the day and the time of day of any time.
        const auto ns = nanoseconds(constant);
        const sema::TimePart part = sema::time_part(from, target);
        return !ns || part == sema::TimePart::All ? ns
               : part == sema::TimePart::Day      ? vm::stdlib::floor_to_day(*ns)
                                                  : vm::stdlib::wrap_to_day(*ns);
    }
    const sema::Type& lint = types_.elementary(E::Lint);
    if (from_time) {
        // Counted in its unit (DivI64, toward zero), then converted as a LINT.
        const auto ns = nanoseconds(constant);
        return ns ? convert(vs::divide(*ns, sema::number_unit(from.elementary)), lint, target)
                  : std::nullopt;
    }
    // A number as a LINT (a real rounded to nearest, saturating), times the unit (Mul64).
    const auto count = convert(constant, from, lint);
    return count ? std::optional<Constant>(vs::mul(std::get<std::int64_t>(*count),
                                                   sema::number_unit(target.elementary)))
                 : std::nullopt;
}

} // namespace eposp::compiler::types
