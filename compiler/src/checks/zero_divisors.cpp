// E0408: a divisor of '/', MOD, DIV or MOD() that is a constant zero: the division would fail
// at every run, so it is refused when compiling.

#include "body_walk.hpp"
#include "eposp/compiler/sema/symbol.hpp"
#include "pou_checks.hpp"

namespace eposp::compiler::checks {
namespace {

void check_divisor(const PouUnderCheck& check, bool divide, const ast::Expression& divisor) {
    const auto* literal = std::get_if<ast::LiteralExpression>(&divisor.node);
    const auto* real =
        literal != nullptr ? std::get_if<ast::RealLiteral>(&literal->value) : nullptr;
    if ((real != nullptr && real->value == 0.0) ||
        check.program.types().fold_integer(divisor) == 0) {
        check.diagnostics.error(DiagnosticCode::E0408, divisor.range,
                                divide ? "division by zero" : "MOD by zero");
    }
}

} // namespace

void check_zero_divisors(const PouUnderCheck& check) {
    for_each_expression(check.pou.body, [&](const ast::Expression& expression) {
        if (const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node)) {
            if (binary->op == ast::BinaryOperator::Divide ||
                binary->op == ast::BinaryOperator::Modulo) {
                check_divisor(check, binary->op == ast::BinaryOperator::Divide, *binary->right);
            }
            return;
        }
        // DIV(a, b, ...) and MOD(a, b, ...): every input after the first divides.
        const types::CallTarget* target = check.program.call_target(expression);
        const auto* call = std::get_if<ast::CallExpression>(&expression.node);
        if (target == nullptr || call == nullptr ||
            target->kind != types::CallKind::StandardFunction ||
            (target->name != "DIV" && target->name != "MOD")) {
            return;
        }
        bool first = true;
        for (const ast::Argument& argument : call->arguments) {
            const bool enable = argument.name && (sema::fold_case(argument.name->name) == "EN" ||
                                                  sema::fold_case(argument.name->name) == "ENO");
            if (enable || argument.value == nullptr) {
                continue;
            }
            if (!first) {
                check_divisor(check, target->name == "DIV", *argument.value);
            }
            first = false;
        }
    });
}

} // namespace eposp::compiler::checks
