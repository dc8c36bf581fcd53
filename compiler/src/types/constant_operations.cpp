// The constants of operators, conversions and the pure standard functions (TypedProgram::
// constant_of), from their operands' constants, computed by the VM's own templates
// (vm/value_semantics.hpp) in the machine type the VM computes in: the type the typing stage
// gives the operands (operands_of: a small integer inside an expression in DINT), each
// operation wrapping at its width, a division by zero no constant (it traps at run time).

#include "constant_folder.hpp"
#include "eposp/compiler/ascii_case.hpp"
#include "eposp/vm/stdlib/manifest.hpp"
#include "eposp/vm/stdlib/text_functions.hpp"
#include "eposp/vm/value_semantics.hpp"
#include "expression_typer.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>

namespace eposp::compiler::types {

namespace {

namespace vs = vm::detail;
using vm::stdlib::Family;
using vm::stdlib::Operation;

template <typename T>
using Tag = std::type_identity<T>;

/// `f(Tag<T>{})` with T the C++ type the VM holds a value of `scalar` in; nothing for
/// pointers.
template <typename F>
auto with_scalar(vm::Scalar scalar, F f) -> decltype(f(Tag<std::int32_t>{})) {
    switch (scalar) {
    case vm::Scalar::Bool:
        return f(Tag<vm::BoolByte>{});
    case vm::Scalar::I8:
        return f(Tag<std::int8_t>{});
    case vm::Scalar::I16:
        return f(Tag<std::int16_t>{});
    case vm::Scalar::I32:
        return f(Tag<std::int32_t>{});
    case vm::Scalar::I64:
        return f(Tag<std::int64_t>{});
    case vm::Scalar::U8:
        return f(Tag<std::uint8_t>{});
    case vm::Scalar::U16:
        return f(Tag<std::uint16_t>{});
    case vm::Scalar::U32:
        return f(Tag<std::uint32_t>{});
    case vm::Scalar::U64:
        return f(Tag<std::uint64_t>{});
    case vm::Scalar::F32:
        return f(Tag<float>{});
    case vm::Scalar::F64:
        return f(Tag<double>{});
    default:
        return std::nullopt;
    }
}

template <typename T>
Constant to_constant(T value) {
    if constexpr (std::is_same_v<T, vm::BoolByte>) {
        return static_cast<std::uint8_t>(value) != 0;
    } else if constexpr (std::is_floating_point_v<T>) {
        return static_cast<double>(value);
    } else if constexpr (std::is_signed_v<T>) {
        return static_cast<std::int64_t>(value);
    } else {
        return static_cast<std::uint64_t>(value);
    }
}

/// A constant as a value of T, converted as the VM converts (vs::convert: integers wrap, a
/// real rounds to nearest and saturates); a string is none.
template <typename T>
std::optional<T> scalar_value(const Constant& constant) {
    return std::visit(
        [](const auto& value) -> std::optional<T> {
            using V = std::decay_t<decltype(value)>;
            if constexpr (std::is_same_v<V, std::string> || std::is_same_v<V, std::u16string>) {
                return std::nullopt;
            } else if constexpr (std::is_same_v<V, bool>) {
                return vs::convert<T>(static_cast<vm::BoolByte>(value ? 1 : 0));
            } else {
                return vs::convert<T>(value);
            }
        },
        constant);
}

/// Whether a value of `type` is a number the VM converts by vs::convert (not a duration or a
/// date, counted in other units, nor a string or reference).
bool plain_scalar(const sema::Type& type) {
    return sema::is_scalar(type) && !sema::is_time_like(type) &&
           type.kind != sema::TypeKind::Reference && type.kind != sema::TypeKind::Null;
}

template <typename T>
constexpr bool kInteger = std::is_integral_v<T>;

bool is_arithmetic(ast::BinaryOperator op) {
    using Op = ast::BinaryOperator;
    return op == Op::Add || op == Op::Subtract || op == Op::Multiply || op == Op::Divide ||
           op == Op::Modulo;
}

/// Whether the typing stage may hold `expression` in DINT while it feeds its operator: an
/// arithmetic operation or a negation (ExpressionTyper::held).
bool holdable(const ast::Expression& expression) {
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        return unary->op == ast::UnaryOperator::Negate;
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    return binary != nullptr && is_arithmetic(binary->op);
}

template <typename T>
std::optional<Constant> binary_in(ast::BinaryOperator op, T l, T r) {
    using Op = ast::BinaryOperator;
    using Bits = std::conditional_t<std::is_same_v<T, vm::BoolByte>, std::uint8_t, T>;
    const auto bits = [](auto value) {
        return static_cast<Bits>(value);
    };
    switch (op) {
    case Op::Equal:
        return bits(l) == bits(r);
    case Op::NotEqual:
        return bits(l) != bits(r);
    case Op::Less:
        return bits(l) < bits(r);
    case Op::Greater:
        return bits(r) < bits(l);
    case Op::LessEqual:
        return bits(l) <= bits(r);
    case Op::GreaterEqual:
        return bits(r) <= bits(l);
    case Op::And:
    case Op::Or:
    case Op::Xor:
        if constexpr (std::is_floating_point_v<T>) {
            return std::nullopt;
        } else {
            const Bits x = bits(l);
            const Bits y = bits(r);
            return to_constant(static_cast<T>(op == Op::And  ? x & y
                                              : op == Op::Or ? x | y
                                                             : x ^ y));
        }
    default:
        break;
    }
    if constexpr (std::is_same_v<T, vm::BoolByte>) {
        return std::nullopt;
    } else {
        switch (op) {
        case Op::Add:
            return to_constant(vs::add(l, r));
        case Op::Subtract:
            return to_constant(vs::sub(l, r));
        case Op::Multiply:
            return to_constant(vs::mul(l, r));
        case Op::Divide:
            if constexpr (kInteger<T>) {
                if (r == 0) {
                    return std::nullopt;
                }
            }
            return to_constant(vs::divide(l, r));
        case Op::Modulo:
            if constexpr (kInteger<T>) {
                if (r != 0) {
                    return to_constant(vs::modulo(l, r));
                }
            }
            return std::nullopt;
        default:
            return std::nullopt;
        }
    }
}

/// A comparison of two texts of one kind (EQ_STRING, LT_WSTRING...): their order
/// (vm/stdlib/text_functions.hpp) compared with 0.
std::optional<Constant> text_comparison(ast::BinaryOperator op, const Constant& left,
                                        const Constant& right) {
    return std::visit(
        [op](const auto& l, const auto& r) -> std::optional<Constant> {
            using L = std::decay_t<decltype(l)>;
            if constexpr (!std::is_same_v<L, std::decay_t<decltype(r)>> ||
                          (!std::is_same_v<L, std::string> && !std::is_same_v<L, std::u16string>)) {
                return std::nullopt;
            } else {
                using Char = typename L::value_type;
                const std::strong_ordering order = vm::stdlib::text_order<Char>(l, r);
                const std::int32_t sign = order < 0 ? -1 : order > 0 ? 1 : 0;
                return op >= ast::BinaryOperator::Less && op <= ast::BinaryOperator::NotEqual
                           ? binary_in<std::int32_t>(op, sign, 0)
                           : std::nullopt;
            }
        },
        left, right);
}

/// A binary operation on two constants of `type`'s values.
std::optional<Constant> binary_constant(ast::BinaryOperator op, const Constant& left,
                                        const Constant& right, const sema::Type& type) {
    if (type.kind == sema::TypeKind::String) {
        return text_comparison(op, left, right);
    }
    return with_scalar(sema::scalar_of(type), [&](auto tag) -> std::optional<Constant> {
        using T = typename decltype(tag)::type;
        const auto l = scalar_value<T>(left);
        const auto r = scalar_value<T>(right);
        return l && r ? binary_in(op, *l, *r) : std::nullopt;
    });
}

/// Whether `a <= b` in `type`, as the selection functions compare (codegen's jump_if_at_most).
std::optional<bool> at_most(const Constant& a, const Constant& b, const sema::Type& type) {
    const auto result = binary_constant(ast::BinaryOperator::LessEqual, a, b, type);
    return result ? std::optional(std::get<bool>(*result)) : std::nullopt;
}

/// A constant taken as unsigned 64 bits, a negative one as its two's complement (a shift
/// count, a MUX selector).
std::optional<std::uint64_t> raw_bits(const Constant& constant) {
    if (const auto* i = std::get_if<std::int64_t>(&constant)) {
        return static_cast<std::uint64_t>(*i);
    }
    if (const auto* u = std::get_if<std::uint64_t>(&constant)) {
        return *u;
    }
    return std::nullopt;
}

std::optional<Constant> shift(Operation operation, const Constant& value, std::uint64_t count,
                              const sema::Type& type) {
    // The width's own instruction (Shl16, ...) on the unsigned type of that width.
    const vm::Scalar scalar = sema::scalar_of(type);
    const auto unsigned_scalar = [](vm::Scalar s) {
        switch (s) {
        case vm::Scalar::I8:
            return vm::Scalar::U8;
        case vm::Scalar::I16:
            return vm::Scalar::U16;
        case vm::Scalar::I32:
            return vm::Scalar::U32;
        case vm::Scalar::I64:
            return vm::Scalar::U64;
        default:
            return s;
        }
    };
    return with_scalar(unsigned_scalar(scalar), [&](auto tag) -> std::optional<Constant> {
        using U = typename decltype(tag)::type;
        if constexpr (!std::is_integral_v<U> || std::is_signed_v<U>) {
            return std::nullopt;
        } else {
            const auto x = scalar_value<U>(value);
            if (!x) {
                return std::nullopt;
            }
            // A count beyond every width shifts every bit out (codegen keeps it beyond).
            const auto n = static_cast<std::uint32_t>(std::min<std::uint64_t>(count, 64));
            const auto rotation = static_cast<std::uint32_t>(count % vs::kBits<U>);
            const U bits = operation == Operation::ShiftLeft    ? vs::shift_left(*x, n)
                           : operation == Operation::ShiftRight ? vs::shift_right(*x, n)
                           : operation == Operation::RotateLeft ? vs::rotate_left(*x, rotation)
                                                                : vs::rotate_right(*x, rotation);
            // Back as a value of the type (an INT's bits read signed).
            return with_scalar(scalar, [&](auto own) -> std::optional<Constant> {
                using T = typename decltype(own)::type;
                return to_constant(static_cast<T>(bits));
            });
        }
    });
}

/// Whether `op` on `l` and `r` wraps around in T: its exact result is no value of T.
template <typename T>
bool wraps_in(ast::BinaryOperator op, T l, T r) {
    if constexpr (!std::is_integral_v<T>) {
        return false;
    } else {
        T exact{};
        switch (op) {
        case ast::BinaryOperator::Add:
            return __builtin_add_overflow(l, r, &exact);
        case ast::BinaryOperator::Subtract:
            return __builtin_sub_overflow(l, r, &exact);
        case ast::BinaryOperator::Multiply:
            return __builtin_mul_overflow(l, r, &exact);
        case ast::BinaryOperator::Divide:
            if constexpr (std::is_signed_v<T>) {
                return r == -1 && l == std::numeric_limits<T>::min();
            }
            return false;
        default:
            return false;
        }
    }
}

} // namespace

std::optional<Constant> ConstantFolder::convert(const Constant& constant, const sema::Type& from,
                                                const sema::Type& to) const {
    const sema::Type& target = types_.unranged(to);
    const auto* text = std::get_if<std::string>(&constant);
    const auto* wide = std::get_if<std::u16string>(&constant);
    if (text != nullptr || wide != nullptr || target.kind == sema::TypeKind::String) {
        // A STRING or WSTRING keeps the characters its capacity holds, as when stored.
        const bool strings = from.kind == sema::TypeKind::String &&
                             target.kind == sema::TypeKind::String && from.wide == target.wide;
        if (strings && !target.wide && text != nullptr) {
            return text->substr(0, target.capacity);
        }
        if (strings && target.wide && wide != nullptr) {
            return wide->substr(0, target.capacity);
        }
        return std::nullopt;
    }
    const auto duration = [](const sema::Type& type) {
        return type.kind == sema::TypeKind::Elementary &&
               (type.elementary == ast::ElementaryType::Time ||
                type.elementary == ast::ElementaryType::Ltime);
    };
    if (&from == &target || (sema::is_time_like(from) && from.elementary == target.elementary) ||
        (duration(from) && duration(target)) ||
        (sema::is_time_like(from) && sema::converts_implicitly(from, target))) {
        return constant; // a time is ns in its short and its long form (DATE and LDATE...)
    }
    if (!plain_scalar(from) || !plain_scalar(target)) {
        return std::nullopt;
    }
    return with_scalar(sema::scalar_of(target), [&](auto tag) -> std::optional<Constant> {
        using T = typename decltype(tag)::type;
        const auto value = scalar_value<T>(constant);
        return value ? std::optional(to_constant(*value)) : std::nullopt;
    });
}

std::optional<ConstantFolder::Held> ConstantFolder::held(const ast::Expression& expression) const {
    // An operation on small integers is held as computed, in DINT, while it feeds its operator
    // (codegen's operand_value, Value::iec); anything else as its type. Its operator marks it
    // so and records its constant as computed (the typing stage's hold()).
    const Constant* value = program_.constant_of(expression);
    const sema::Type* type = program_.type_of(expression);
    if (value == nullptr || type == nullptr) {
        return std::nullopt;
    }
    const sema::Type& own = types_.unranged(*type);
    const sema::Type* computed = holdable(expression) ? program_.operands_of(expression) : nullptr;
    return Held{*value, computed != nullptr ? computed : &own};
}

std::optional<Constant> ConstantFolder::computed(const ast::Expression& expression) const {
    const sema::Type* in = program_.operands_of(expression);
    if (in == nullptr) {
        return std::nullopt;
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        return negation(*unary, *in);
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    return binary != nullptr ? operation(*binary, *in) : std::nullopt;
}

std::optional<Constant> ConstantFolder::operation(const ast::BinaryExpression& node,
                                                  const sema::Type& computed) const {
    const auto left = held(*node.left);
    const auto right = left ? held(*node.right) : std::nullopt;
    if (!right) {
        return std::nullopt;
    }
    const auto l = convert(left->value, *left->type, computed);
    const auto r = l ? convert(right->value, *right->type, computed) : std::nullopt;
    return r ? binary_constant(node.op, *l, *r, computed) : std::nullopt;
}

std::optional<Constant> ConstantFolder::negation(const ast::UnaryExpression& node,
                                                 const sema::Type& computed) const {
    const auto operand = held(*node.operand);
    const auto value = operand ? convert(operand->value, *operand->type, computed) : std::nullopt;
    if (!value) {
        return std::nullopt;
    }
    return with_scalar(sema::scalar_of(computed), [&](auto tag) -> std::optional<Constant> {
        using T = typename decltype(tag)::type;
        const auto x = scalar_value<T>(*value);
        if constexpr (std::is_same_v<T, vm::BoolByte>) {
            return std::nullopt;
        } else {
            return x ? std::optional(to_constant(vs::neg(*x))) : std::nullopt;
        }
    });
}

std::optional<Constant> ConstantFolder::unary_value(const ast::Expression& expression,
                                                    const ast::UnaryExpression& node) const {
    // Computed as code generation's unary() does: in its operand's type, or in DINT where the
    // typing stage holds it there (operands_of), then cut to its type.
    const Constant* value = program_.constant_of(*node.operand);
    const sema::Type* operand_type = program_.type_of(*node.operand);
    if (value == nullptr || operand_type == nullptr) {
        return std::nullopt;
    }
    if (node.op == ast::UnaryOperator::Plus) {
        return *value;
    }
    const sema::Type& type = types_.unranged(*operand_type);
    if (!plain_scalar(type) && (node.op == ast::UnaryOperator::Not || !sema::is_time_like(type))) {
        return std::nullopt;
    }
    if (node.op == ast::UnaryOperator::Negate) {
        const sema::Type* in = program_.operands_of(expression);
        const auto negated = negation(node, in != nullptr ? *in : type);
        return negated && in != nullptr ? convert(*negated, *in, type) : negated;
    }
    return with_scalar(sema::scalar_of(type), [&](auto tag) -> std::optional<Constant> {
        using T = typename decltype(tag)::type;
        const auto x = scalar_value<T>(*value);
        if (!x) {
            return std::nullopt;
        }
        if constexpr (std::is_same_v<T, vm::BoolByte>) {
            return std::optional<Constant>(*x == vm::BoolByte{0});
        } else if constexpr (std::is_floating_point_v<T>) {
            return std::nullopt;
        } else {
            return to_constant(static_cast<T>(~*x));
        }
    });
}

std::optional<Constant> ConstantFolder::binary_value(const ast::Expression& expression,
                                                     const ast::BinaryExpression& node,
                                                     const sema::Type& type) const {
    if (node.op == ast::BinaryOperator::Power) {
        return power_value(node, type); // constant_real_functions.cpp
    }
    const sema::Type* computed = program_.operands_of(expression);
    if (computed == nullptr) {
        return time_value(node, type); // constant_time_operations.cpp
    }
    // As eval() gives it: an arithmetic result computed wider than its type cut to the type
    // (recorded as computed where it feeds an operator, computed_in).
    auto value = operation(node, *computed);
    if (!value || std::holds_alternative<bool>(*value)) {
        return value;
    }
    return convert(*value, *computed, type);
}

std::optional<Constant> ConstantFolder::call_value(const ast::Expression& expression,
                                                   const ast::CallExpression& node) const {
    const CallTarget* target = program_.call_target(expression);
    if (target == nullptr || target->result == nullptr ||
        (target->kind != CallKind::Conversion && target->kind != CallKind::StandardFunction)) {
        return std::nullopt;
    }
    // The families without an overload's operand type: an array's bounds (its argument is no
    // constant) and the string functions.
    const vm::stdlib::StandardFunction* function = vm::stdlib::find_standard_function(target->name);
    const bool text = function != nullptr && function->family == Family::Text;
    if (function != nullptr && function->family == Family::Bound) {
        return bound_value(node, target->name == "UPPER_BOUND"); // constant_array_bounds.cpp
    }
    if (target->operand == nullptr && !text) {
        return std::nullopt;
    }
    // Most calls have an input that is no constant. A call with EN may not run: no constant.
    // ENO (of a call without EN, TRUE) is an output: not the function's value.
    for (const ast::Argument& argument : node.arguments) {
        if (argument.name && equal_ignoring_case(argument.name->name, "ENO")) {
            continue;
        }
        if (program_.constant_of(*argument.value) == nullptr ||
            (argument.name && equal_ignoring_case(argument.name->name, "EN"))) {
            return std::nullopt;
        }
    }
    // Each input stores its argument: the argument's value (cut to its type) converted to
    // the input's type, the overload's.
    const auto arguments =
        standard_arguments(target->kind == CallKind::Conversion ? "TO" : target->name, node);
    std::vector<Constant> values;
    std::vector<const sema::Type*> types;
    for (const ast::Argument* argument : arguments) {
        const Constant* value =
            argument != nullptr ? program_.constant_of(*argument->value) : nullptr;
        const sema::Type* type = value != nullptr ? program_.type_of(*argument->value) : nullptr;
        if (type == nullptr) {
            return std::nullopt;
        }
        values.push_back(*value);
        types.push_back(&types_.unranged(*type));
    }
    if (values.empty()) {
        return std::nullopt;
    }
    if (text) {
        return text_function(target->name, values, *target->result); // constant_texts.cpp
    }
    const sema::Type& operand = *target->operand;
    if (target->kind == CallKind::Conversion) {
        // A text is converted as it is, of its own type, not cut to the STRING[80] of
        // STRING_TO_INT's input (codegen's conversion() passes it at its own capacity).
        const bool whole_text = types[0]->kind == sema::TypeKind::String &&
                                operand.kind == sema::TypeKind::String &&
                                types[0]->wide == operand.wide;
        const auto source =
            whole_text ? std::optional(values[0]) : convert(values[0], *types[0], operand);
        if (!source || target->name != "TRUNC") {
            // constant_time_operations.cpp: TIME_TO_DINT, DINT_TO_TIME, DT_TO_DATE...
            return source ? explicit_conversion(*source, whole_text ? *types[0] : operand,
                                                *target->result)
                          : std::nullopt;
        }
        // TRUNC as code generation computes it: toward zero into LINT, then through LREAL
        // into DINT, saturating.
        const auto real = std::get_if<double>(&*source);
        return real != nullptr ? std::optional<Constant>(to_constant(vs::convert<std::int32_t>(
                                     static_cast<double>(vs::truncate<std::int64_t>(*real)))))
                               : std::nullopt;
    }
    if (function == nullptr) {
        return std::nullopt;
    }
    // The inputs of the overload, from `first` on.
    const auto inputs = [&](std::size_t first) -> std::optional<std::vector<Constant>> {
        std::vector<Constant> result;
        for (std::size_t i = first; i < values.size(); ++i) {
            auto value = convert(values[i], *types[i], operand);
            if (!value) {
                return std::nullopt;
            }
            result.push_back(std::move(*value));
        }
        return result;
    };
    switch (function->family) {
    case Family::Move:
    case Family::Absolute: {
        const auto in = inputs(0);
        if (!in || function->family == Family::Move) {
            return in ? std::optional(in->front()) : std::nullopt;
        }
        return with_scalar(sema::scalar_of(operand), [&](auto tag) -> std::optional<Constant> {
            using T = typename decltype(tag)::type;
            if constexpr (std::is_same_v<T, vm::BoolByte>) {
                return std::nullopt;
            } else {
                const auto x = scalar_value<T>(in->front());
                return x ? std::optional(to_constant(vs::abs(*x))) : std::nullopt;
            }
        });
    }
    case Family::Arithmetic:
    case Family::Logic:
    case Family::Comparison: {
        const auto in = inputs(0);
        if (!in) {
            return std::nullopt;
        }
        if (function->operation == Operation::Not) {
            return with_scalar(sema::scalar_of(operand), [&](auto tag) -> std::optional<Constant> {
                using T = typename decltype(tag)::type;
                const auto x = scalar_value<T>(in->front());
                if constexpr (std::is_same_v<T, vm::BoolByte>) {
                    return x ? std::optional<Constant>(*x == vm::BoolByte{0}) : std::nullopt;
                } else if constexpr (std::is_integral_v<T>) {
                    return x ? std::optional(to_constant(static_cast<T>(~*x))) : std::nullopt;
                } else {
                    return std::nullopt;
                }
            });
        }
        const auto op = operator_of(function->operation);
        if (!op || in->size() < 2) {
            return std::nullopt;
        }
        // Extensible comparisons hold for each neighbouring pair (table 28), the others fold
        // from left to right.
        if (function->family == Family::Comparison) {
            bool all = true;
            for (std::size_t i = 1; i < in->size(); ++i) {
                const auto pair = binary_constant(*op, (*in)[i - 1], (*in)[i], operand);
                if (!pair) {
                    return std::nullopt;
                }
                all = all && std::get<bool>(*pair);
            }
            return all;
        }
        std::optional<Constant> result = in->front();
        for (std::size_t i = 1; result && i < in->size(); ++i) {
            result = binary_constant(*op, *result, (*in)[i], operand);
        }
        return result;
    }
    case Family::Shift: {
        const auto in = convert(values[0], *types[0], operand);
        const auto count = raw_bits(values[1]);
        return in && count ? shift(function->operation, *in, *count, operand) : std::nullopt;
    }
    case Family::Select: {
        const auto in = inputs(1);
        const bool* g = std::get_if<bool>(&values[0]);
        return in && g != nullptr ? std::optional((*in)[*g ? 1 : 0]) : std::nullopt;
    }
    case Family::Real:
    case Family::Power: {
        // constant_real_functions.cpp; EXPT's exponent is converted to the base's real type too.
        const auto in = inputs(0);
        return in ? real_function(target->name, *in, operand) : std::nullopt;
    }
    case Family::Time: // constant_time_operations.cpp
        return time_function(target->name, values, types, *target->result);
    case Family::Multiplex: {
        // 6.6.2.5.9: K selects IN0..INn; out of range gives IN0 (codegen's selection()).
        const auto in = inputs(1);
        const auto* k = std::get_if<std::int64_t>(&values[0]);
        const auto* uk = std::get_if<std::uint64_t>(&values[0]);
        if (!in || (k == nullptr && uk == nullptr)) {
            return std::nullopt;
        }
        const bool inside = k != nullptr ? *k >= 1 && static_cast<std::uint64_t>(*k) < in->size()
                                         : *uk >= 1 && *uk < in->size();
        return (*in)[inside ? static_cast<std::size_t>(k != nullptr ? *k : *uk) : 0];
    }
    case Family::Limit: {
        const auto in = inputs(0);
        if (!in || in->size() != 3) {
            return std::nullopt;
        }
        const auto above_low = at_most((*in)[0], (*in)[1], operand);
        const auto below_high = above_low ? at_most((*in)[1], (*in)[2], operand) : std::nullopt;
        if (!below_high) {
            return std::nullopt;
        }
        return !*above_low ? (*in)[0] : *below_high ? (*in)[1] : (*in)[2];
    }
    case Family::Extreme: {
        const auto in = inputs(0);
        if (!in) {
            return std::nullopt;
        }
        const bool maximum = function->operation == Operation::Maximum;
        Constant result = in->front();
        for (std::size_t i = 1; i < in->size(); ++i) {
            const auto keep =
                maximum ? at_most((*in)[i], result, operand) : at_most(result, (*in)[i], operand);
            if (!keep) {
                return std::nullopt;
            }
            if (!*keep) {
                result = (*in)[i];
            }
        }
        return result;
    }
    default:
        return std::nullopt;
    }
}

bool ConstantFolder::wraps(const ast::Expression& expression) const {
    // A result computed in DINT and cut to its INT where it is not held (as stored).
    const auto cut = [&] {
        const auto wide = computed(expression);
        const Constant* recorded = program_.constant_of(expression);
        return wide && recorded != nullptr && !same_number(*wide, *recorded);
    };
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        // -x wraps at the most negative value of a signed type, at any other than 0 of an
        // unsigned one.
        const auto operand =
            unary->op == ast::UnaryOperator::Negate ? held(*unary->operand) : std::nullopt;
        if (!operand) {
            return false;
        }
        const sema::Type* computed_in = program_.operands_of(expression);
        const sema::Type& in = computed_in != nullptr ? *computed_in : *operand->type;
        const auto value = convert(operand->value, *operand->type, in);
        const bool negation_wraps =
            value && with_scalar(sema::scalar_of(in), [&](auto tag) -> std::optional<bool> {
                         using T = typename decltype(tag)::type;
                         if constexpr (!std::is_integral_v<T>) {
                             return false;
                         } else {
                             const auto x = scalar_value<T>(*value);
                             return x && (std::is_signed_v<T> ? *x == std::numeric_limits<T>::min()
                                                              : *x != 0);
                         }
                     }).value_or(false);
        return negation_wraps || (computed_in != nullptr && cut());
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    const sema::Type* in = binary != nullptr ? program_.operands_of(expression) : nullptr;
    if (in == nullptr || !is_arithmetic(binary->op) ||
        (!sema::is_integer(*in) && !sema::is_bit_string(*in))) {
        return false;
    }
    const auto left = held(*binary->left);
    const auto right = left ? held(*binary->right) : std::nullopt;
    const auto l = right ? convert(left->value, *left->type, *in) : std::nullopt;
    const auto r = l ? convert(right->value, *right->type, *in) : std::nullopt;
    if (!r) {
        return false;
    }
    const bool operation_wraps =
        with_scalar(sema::scalar_of(*in), [&](auto tag) -> std::optional<bool> {
            using T = typename decltype(tag)::type;
            const auto x = scalar_value<T>(*l);
            const auto y = scalar_value<T>(*r);
            return x && y && wraps_in(binary->op, *x, *y);
        }).value_or(false);
    return operation_wraps || cut();
}

} // namespace eposp::compiler::types
