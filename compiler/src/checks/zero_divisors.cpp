// E0408: a divisor of '/', MOD, DIV(), MOD() or DIV_TIME() that is a constant zero: the division
// would fail at every run, so it is refused when compiling.

#include "calls.hpp"
#include "pou_checks.hpp"

namespace eposp::compiler::checks {
namespace {

void check_divisor(const PouUnderCheck& check, bool divide, const ast::Expression& divisor) {
    // A zero of any number type: `x / 0` divides a REAL by a REAL 0.0.
    const types::Constant* value = check.program.constant_of(divisor);
    const auto zero = [](const auto& number) {
        using V = std::decay_t<decltype(number)>;
        if constexpr (std::is_same_v<V, bool> || std::is_same_v<V, std::string> ||
                      std::is_same_v<V, std::u16string>) {
            return false;
        } else {
            return number == V{0};
        }
    };
    if (value != nullptr && std::visit(zero, *value)) {
        check.diagnostics.error(DiagnosticCode::E0408, divisor.range,
                                divide ? "division by zero" : "MOD by zero");
    }
}

// DIV(a, b, ...), MOD(a, b, ...) and DIV_TIME(t, n): every input after the first divides.
void check_call(const PouUnderCheck& check, const ast::Expression& expression,
                const ast::CallExpression& call) {
    const types::CallTarget* target = check.program.call_target(expression);
    if (target == nullptr || target->kind != types::CallKind::StandardFunction ||
        (target->name != "DIV" && target->name != "MOD" && target->name != "DIV_TIME")) {
        return;
    }
    bool first = true;
    for (const ast::Argument& argument : call.arguments) {
        if (is_enable_argument(argument) || argument.value == nullptr) {
            continue;
        }
        if (!first) {
            check_divisor(check, target->name != "MOD", *argument.value);
        }
        first = false;
    }
}

} // namespace

void check_zero_divisors(const PouUnderCheck& check) {
    for (const ast::Expression* expression : check.body.expressions()) {
        if (const auto* binary = std::get_if<ast::BinaryExpression>(&expression->node)) {
            if (binary->op == ast::BinaryOperator::Divide ||
                binary->op == ast::BinaryOperator::Modulo) {
                check_divisor(check, binary->op == ast::BinaryOperator::Divide, *binary->right);
            }
        } else if (const auto* call = std::get_if<ast::CallExpression>(&expression->node)) {
            check_call(check, *expression, *call);
        }
    }
}

} // namespace eposp::compiler::checks
