// Operators typed (table 71): operands brought to their common type by the widening of figure
// 11, time and date arithmetic (table 30), the operator's own rules.

#include "constant_folder.hpp"
#include "expression_typer.hpp"

#include <fmt/format.h>

namespace eposp::compiler::types {

namespace {

bool is_small_integer(const sema::Type& type) {
    return sema::is_integer(type) && type.size < 4;
}

bool is_arithmetic(ast::BinaryOperator op) {
    using Op = ast::BinaryOperator;
    return op == Op::Add || op == Op::Subtract || op == Op::Multiply || op == Op::Divide ||
           op == Op::Modulo;
}

} // namespace

bool ExpressionTyper::held(const ast::Expression& operand) const {
    const sema::Type* type = program_.type_of(operand);
    if (type == nullptr || !is_small_integer(program_.types().unranged(*type))) {
        return false;
    }
    if (const auto* binary = std::get_if<ast::BinaryExpression>(&operand.node)) {
        return is_arithmetic(binary->op);
    }
    const auto* unary = std::get_if<ast::UnaryExpression>(&operand.node);
    return unary != nullptr && unary->op == ast::UnaryOperator::Negate &&
           !is_untyped_literal(operand);
}

void ExpressionTyper::hold(const ast::Expression& operand) {
    computed_at(operand, elementary(E::Dint));
    // Its constant is the value its operator computes with, not cut to its type.
    if (auto value = program_.constants().computed(operand)) {
        record_constant(operand, std::move(*value));
    }
}

void ExpressionTyper::computed_in(const ast::Expression& expression,
                                  const ast::BinaryExpression& node, const sema::Type& common) {
    // SINT, INT, USINT and UINT are computed in DINT inside an expression and cut to their type
    // where the result is stored, as CODESYS and C do (docs/st-language.md): `(a * b) MOD 1000`
    // does not overflow at INT. An arithmetic operand of small integers (held()) is held in
    // DINT, and an operation on one is computed in DINT too; AND, OR and XOR then cut their
    // result at once to their type, whose bits they are. An input of a function stores its
    // argument, so the operands of ADD, GT, ... are not held (standard_function_typing.cpp).
    const auto small = [&](const ast::Expression& operand) {
        const sema::Type* type = program_.type_of(operand);
        return type != nullptr && is_small_integer(program_.types().unranged(*type));
    };
    const bool wide =
        small(*node.left) && small(*node.right) && (held(*node.left) || held(*node.right));
    for (const ast::Expression* operand : {node.left.get(), node.right.get()}) {
        if (held(*operand)) {
            hold(*operand);
        }
    }
    computed_at(expression, wide ? elementary(E::Dint) : common);
}

void ExpressionTyper::power_input(const ast::Expression& input, const sema::Type& real) {
    const sema::Type* own = program_.type_of(input);
    if (is_untyped_literal(input) && own != nullptr && sema::is_integer(*own) &&
        sema::converts_implicitly(*own, real)) {
        type(input, &real);
    }
}

void ExpressionTyper::computed_at(const ast::Expression& expression, const sema::Type& type) {
    program_.set_operands(expression, type);
    // An untyped literal operand is a value of the type its operation computes in (`i * 7` on
    // INTs computes in DINT: its 7 is a DINT), as unify()'s literals take their common type;
    // literals have no side effects, so typing one again changes nothing else. (A negation
    // held in DINT has no literal operand: held().)
    const auto* node = std::get_if<ast::BinaryExpression>(&expression.node);
    if (node == nullptr) {
        return;
    }
    for (const ast::Expression* operand : {node->left.get(), node->right.get()}) {
        if (is_untyped_literal(*operand) && numeric_context(&type) &&
            program_.type_of(*operand) != &type) {
            this->type(*operand, &type);
        }
    }
}

const sema::Type* ExpressionTyper::unary(const ast::Expression& expression,
                                         const ast::UnaryExpression& node,
                                         const sema::Type* expected) {
    const sema::Type* operand = type(*node.operand, expected);
    if (operand == nullptr) {
        return nullptr;
    }
    const sema::Type& plain = program_.types().unranged(*operand);
    if (node.op == ast::UnaryOperator::Not) {
        if (!sema::is_bool(plain) && !sema::is_bit_string(plain) && !sema::is_integer(plain)) {
            return fail(DiagnosticCode::E0304, expression.range,
                        fmt::format("NOT needs a BOOL or bit string, not {}", plain.name));
        }
        return &plain;
    }
    if (!sema::is_numeric(plain) && plain.elementary != E::Time && plain.elementary != E::Ltime) {
        return fail(DiagnosticCode::E0304, expression.range,
                    fmt::format("'-' needs a number, not {}", plain.name));
    }
    // `-(a * b)` on small integers negates the product held in DINT (computed_in), and so is
    // computed in DINT itself; `-i` is computed in DINT where its operator holds it.
    if (node.op == ast::UnaryOperator::Negate && held(*node.operand)) {
        hold(*node.operand);
        computed_at(expression, elementary(E::Dint));
    }
    return &plain;
}

const sema::Type* ExpressionTyper::common(const sema::Type& a, const sema::Type& b) {
    const sema::Type& x = program_.types().unranged(a);
    const sema::Type& y = program_.types().unranged(b);
    if (sema::converts_implicitly(x, y)) {
        return &y;
    }
    if (sema::converts_implicitly(y, x)) {
        return &x;
    }
    return nullptr;
}

const sema::Type* ExpressionTyper::time_arithmetic(ast::BinaryOperator op, const sema::Type& left,
                                                   const sema::Type& right,
                                                   const SourceRange& range) {
    // 6.6.2.5.5 table 30: durations add and subtract, a point in time moves by a duration (a
    // TIME_OF_DAY wraps around midnight), two points of one type subtract to a duration.
    const auto operation = op == ast::BinaryOperator::Add ? vm::stdlib::Operation::Add
                                                          : vm::stdlib::Operation::Subtract;
    if (const vm::stdlib::StandardFunction* row = time_row(operation, left, right)) {
        return &elementary(elementary_of(row->time.result));
    }
    return fail(DiagnosticCode::E0303, range,
                fmt::format("this operation is not defined on {} and {} (use the functions of "
                            "IEC 61131-3 table 30)",
                            left.name, right.name));
}

const vm::stdlib::StandardFunction* ExpressionTyper::time_row(vm::stdlib::Operation operation,
                                                              const sema::Type& left,
                                                              const sema::Type& right) {
    const auto takes = [&](const sema::Type& actual, vm::NativeType formal) {
        return sema::converts_implicitly(program_.types().unranged(actual),
                                         elementary(elementary_of(formal)));
    };
    for (const vm::stdlib::StandardFunction& row : vm::stdlib::standard_functions()) {
        const vm::stdlib::TimeRule& rule = row.time;
        if (row.family == vm::stdlib::Family::Time && rule.overloaded &&
            row.operation == operation && takes(left, rule.first) &&
            (rule.scaled ? sema::is_numeric(program_.types().unranged(right))
                         : takes(right, rule.second))) {
            return &row;
        }
    }
    return nullptr;
}

const sema::Type* ExpressionTyper::unify(const std::vector<const ast::Expression*>& operands,
                                         const sema::Type* expected, const SourceRange& range,
                                         const sema::Type* first) {
    // Typed operands first; the untyped literals then take their common type.
    const sema::Type* result = nullptr;
    bool failed = false;
    for (const bool literals : {false, true}) {
        for (const ast::Expression* operand : operands) {
            if (is_untyped_literal(*operand) != literals) {
                continue;
            }
            // A text or NULL takes the others' type only (at the end), not the one expected of
            // the result: `SEL(c, 'a', 'bc')` is a STRING[2] wherever it goes.
            const bool text_or_null = is_context_literal(*operand) && !is_untyped_literal(*operand);
            const sema::Type* context = result != nullptr ? result
                                        : text_or_null    ? nullptr
                                                          : expected;
            if (literals && result != nullptr && !numeric_context(result)) {
                context = nullptr;
            }
            const sema::Type* type = first != nullptr && operand == operands.front()
                                         ? first
                                         : this->type(*operand, context);
            if (type == nullptr) {
                failed = true;
                continue;
            }
            if (result == nullptr) {
                result = &program_.types().unranged(*type);
            } else if (result->kind == sema::TypeKind::String && type->kind == result->kind &&
                       type->wide == result->wide) {
                // Strings of any lengths meet in the longest, which holds each of them.
                result = type->capacity > result->capacity ? type : result;
            } else if (const sema::Type* both = common(*result, *type)) {
                result = both;
            } else {
                diagnostics_.error(DiagnosticCode::E0303, range,
                                   fmt::format("operands of types {} and {} do not match",
                                               result->name, type->name));
                failed = true;
            }
        }
    }
    if (failed) {
        return nullptr;
    }
    // A literal typed before a wider one (`5 > 3000000000`, `'abc' = s`) takes the common type
    // after all; literals have no side effects, so typing one again changes nothing else.
    for (const ast::Expression* operand : operands) {
        if (is_context_literal(*operand) &&
            (numeric_context(result) || !is_untyped_literal(*operand)) &&
            program_.type_of(*operand) != result) {
            type(*operand, result);
        }
    }
    return result;
}

const sema::Type* ExpressionTyper::binary(const ast::Expression& expression,
                                          const ast::BinaryExpression& node,
                                          const sema::Type* expected) {
    using Op = ast::BinaryOperator;
    const SourceRange& range = expression.range;
    switch (node.op) {
    case Op::Power: {
        // EXPT (table 24): IN1 ANY_REAL, IN2 ANY_NUM; the result has IN1's type.
        const sema::Type* base =
            type(*node.left, expected != nullptr && sema::is_real(*expected) ? expected : nullptr);
        const sema::Type* exponent = type(*node.right, nullptr);
        if (base == nullptr || exponent == nullptr) {
            return nullptr;
        }
        for (const sema::Type* operand : {base, exponent}) {
            if (!sema::is_numeric(program_.types().unranged(*operand))) {
                return fail(DiagnosticCode::E0304, range,
                            fmt::format("'**' needs numbers, not {}", operand->name));
            }
        }
        const sema::Type& real = sema::is_real(*base) ? *base : elementary(E::Lreal);
        power_input(*node.left, real);
        power_input(*node.right, real);
        return &real;
    }
    case Op::Less:
    case Op::Greater:
    case Op::LessEqual:
    case Op::GreaterEqual:
    case Op::Equal:
    case Op::NotEqual: {
        const sema::Type* operands = unify({node.left.get(), node.right.get()}, nullptr, range);
        if (operands != nullptr && operands->kind != sema::TypeKind::String &&
            !sema::is_scalar(*operands)) {
            return fail(DiagnosticCode::E0304, range,
                        fmt::format("values of type {} cannot be compared", operands->name));
        }
        if (operands == nullptr) {
            return nullptr;
        }
        computed_in(expression, node, *operands);
        return &elementary(E::Bool);
    }
    case Op::And:
    case Op::Or:
    case Op::Xor: {
        const sema::Type* operands = unify({node.left.get(), node.right.get()}, expected, range);
        if (operands != nullptr && !sema::is_bool(*operands) && !sema::is_bit_string(*operands) &&
            !sema::is_integer(*operands)) {
            return fail(
                DiagnosticCode::E0304, range,
                fmt::format("AND, OR and XOR need BOOL or bit strings, not {}", operands->name));
        }
        if (operands != nullptr) {
            computed_in(expression, node, *operands);
        }
        return operands;
    }
    default:
        break;
    }
    // The left operand decides first whether this is a TIME scaled by a number (table 30) or
    // a pointer moved by a number of bytes.
    const sema::Type* left = nullptr;
    if (node.op != Op::Modulo && !is_untyped_literal(*node.left)) {
        const bool scale = node.op == Op::Multiply || node.op == Op::Divide;
        // A product's left operand is typed without a TIME context, which would make a TIME of
        // its literals; a numeric context still types them (`x := 2 * 3 * 5` with x an INT).
        left = type(*node.left, !scale || numeric_context(expected) ? expected : nullptr);
        if (left == nullptr) {
            type(*node.right, nullptr);
            return nullptr;
        }
        if (scale && (left->elementary == E::Time || left->elementary == E::Ltime) &&
            left->kind == sema::TypeKind::Elementary) {
            const sema::Type* factor = type(*node.right, &elementary(E::Lint));
            if (factor != nullptr && !sema::is_numeric(*factor)) {
                return fail(DiagnosticCode::E0304, node.right->range,
                            fmt::format("a TIME is multiplied or divided by a number, not {}",
                                        factor->name));
            }
            return factor != nullptr ? left : nullptr;
        }
        if (!scale && left->kind == sema::TypeKind::Reference) {
            const sema::Type* bytes = type(*node.right, &elementary(E::Lint));
            if (bytes != nullptr && !sema::is_integer(program_.types().unranged(*bytes))) {
                return fail(DiagnosticCode::E0304, node.right->range,
                            fmt::format("a pointer moves by a whole number of bytes, not by a {}",
                                        bytes->name));
            }
            return bytes != nullptr ? left : nullptr;
        }
        if (!scale && sema::is_time_like(*left)) {
            const sema::Type* right = type(*node.right, nullptr);
            return right != nullptr ? time_arithmetic(node.op, *left, *right, range) : nullptr;
        }
    }
    const sema::Type* operands = unify({node.left.get(), node.right.get()}, expected, range, left);
    if (operands == nullptr) {
        return nullptr;
    }
    if (node.op == Op::Modulo && !sema::is_integer(*operands) && !sema::is_bit_string(*operands)) {
        return fail(DiagnosticCode::E0304, range,
                    fmt::format("MOD needs integers, not {}", operands->name));
    }
    if (sema::is_numeric(*operands) || sema::is_bit_string(*operands)) {
        computed_in(expression, node, *operands);
        return operands;
    }
    return fail(DiagnosticCode::E0304, range,
                fmt::format("arithmetic needs numbers, not {}", operands->name));
}

std::optional<ast::BinaryOperator> operator_of(vm::stdlib::Operation operation) {
    using Op = ast::BinaryOperator;
    using vm::stdlib::Operation;
    switch (operation) {
    case Operation::Add:
        return Op::Add;
    case Operation::Subtract:
        return Op::Subtract;
    case Operation::Multiply:
        return Op::Multiply;
    case Operation::Divide:
        return Op::Divide;
    case Operation::Modulo:
        return Op::Modulo;
    case Operation::And:
        return Op::And;
    case Operation::Or:
        return Op::Or;
    case Operation::Xor:
        return Op::Xor;
    case Operation::Less:
        return Op::Less;
    case Operation::Greater:
        return Op::Greater;
    case Operation::LessEqual:
        return Op::LessEqual;
    case Operation::GreaterEqual:
        return Op::GreaterEqual;
    case Operation::Equal:
        return Op::Equal;
    case Operation::NotEqual:
        return Op::NotEqual;
    default:
        return std::nullopt;
    }
}

} // namespace eposp::compiler::types
